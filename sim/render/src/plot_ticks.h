#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace dream::render {

// A round tick spacing (1, 2 or 5 times a power of ten) giving about `ticks` ticks over `span`.
inline double TickSpacing(double span, int ticks) {
  const double raw = span / ticks;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double factor : {1.0, 2.0, 5.0}) {
    if (raw <= factor * power) return factor * power;
  }
  return 10 * power;
}

// A tick's label with as many decimals as the spacing needs.
inline std::string TickText(double value, double spacing) {
  char text[32];
  const int decimals = spacing >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(spacing) - 1e-9));
  std::snprintf(text, sizeof(text), "%.*f", decimals, std::abs(value) < spacing * 1e-6 ? 0.0 : value);
  return text;
}

}  // namespace dream::render
