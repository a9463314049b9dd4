#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace dream::world {

/// printf into a std::string, of any length: for numbers in messages and
/// reports that must keep a given precision ("%.2f s", "%g", "%.10g").
template <typename... Args>
std::string PrintfText(const char* format, Args... args) {
  const int size = std::snprintf(nullptr, 0, format, args...);
  if (size <= 0) return std::string();
  std::string text(static_cast<std::size_t>(size) + 1, '\0');
  std::snprintf(text.data(), text.size(), format, args...);
  text.resize(static_cast<std::size_t>(size));
  return text;
}

}  // namespace dream::world
