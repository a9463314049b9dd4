#include "dream/render/viewport.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace dream::render {
namespace {

// "0.4", "-1.25", "0": millimetres kept, no trailing zeros.
std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f", std::abs(value) < 5e-4 ? 0.0 : value);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

Viewport Viewport::Parse(const std::string& text, const world::Arena& arena) {
  const std::string usage = "--viewport " + text.substr(0, 80) + ": expected XMIN,YMIN,XMAX,YMAX in metres";
  std::vector<double> values;
  size_t at = 0;
  while (at <= text.size() && values.size() < 5) {
    const size_t comma = text.find(',', at);
    const std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (part.empty() || used != part.size()) throw std::invalid_argument(usage + " (not a number: '" + part + "')");
    values.push_back(value);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  if (values.size() != 4) throw std::invalid_argument(usage + " (four numbers)");
  const Viewport viewport{values[0], values[1], values[2], values[3]};
  viewport.Check(arena, "--viewport");
  return viewport;
}

void Viewport::Check(const world::Arena& arena, const std::string& what) const {
  const std::string value = what + " " + Text();
  for (const double v : {x_min_m, y_min_m, x_max_m, y_max_m}) {
    if (!std::isfinite(v)) throw std::invalid_argument(what + ": a value is not a finite number");
  }
  if (width_m() < kMinSpanM || height_m() < kMinSpanM) {
    throw std::invalid_argument(value + ": XMAX - XMIN and YMAX - YMIN must each be at least " + Metres(kMinSpanM) +
                                " m");
  }
  if (x_min_m < arena.x_min_m - kMaxOutsideM || x_max_m > arena.x_max_m + kMaxOutsideM ||
      y_min_m < arena.y_min_m - kMaxOutsideM || y_max_m > arena.y_max_m + kMaxOutsideM) {
    throw std::invalid_argument(value + ": reaches more than " + Metres(kMaxOutsideM) + " m past the arena (" +
                                Metres(arena.x_min_m) + ".." + Metres(arena.x_max_m) + " x " + Metres(arena.y_min_m) +
                                ".." + Metres(arena.y_max_m) + " m)");
  }
}

std::string Viewport::Text() const {
  return Metres(x_min_m) + "," + Metres(y_min_m) + "," + Metres(x_max_m) + "," + Metres(y_max_m);
}

}  // namespace dream::render
