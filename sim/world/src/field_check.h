#pragma once

#include <cmath>
#include <string>

#include "dream/world/printf_text.h"

namespace dream::sim::field_check {

// Shared wording for IsValid messages: "<field> = <value> ...; allowed: <range>".

inline std::string FormatValue(double value) { return PrintfText("%.10g", value); }

// Writes the message (if error is not null) and returns false, so callers can
// `return Fail(...)`.
inline bool Fail(std::string* error, const std::string& field, double value, const std::string& allowed) {
  if (error != nullptr) {
    *error = field + " = " + FormatValue(value) + " is out of range; allowed: " + allowed;
  }
  return false;
}

inline bool FailWithText(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

inline bool IsPositiveFinite(double value) { return std::isfinite(value) && value > 0.0; }
inline bool IsNonNegativeFinite(double value) { return std::isfinite(value) && value >= 0.0; }

}  // namespace dream::sim::field_check
