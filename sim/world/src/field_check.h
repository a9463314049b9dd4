#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "dream/world/printf_text.h"

namespace dream::world::field_check {

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

// `params` when its IsValid() holds, else std::invalid_argument "<owner>: <IsValid's message>":
// for constructors' member initialisers, so no part is built from bad params.
template <typename Params>
const Params& Checked(const std::string& owner, const Params& params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument(owner + ": " + error);
  return params;
}

inline bool IsPositiveFinite(double value) { return std::isfinite(value) && value > 0.0; }
inline bool IsNonNegativeFinite(double value) { return std::isfinite(value) && value >= 0.0; }

}  // namespace dream::world::field_check
