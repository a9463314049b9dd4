#pragma once

#include <sstream>
#include <string>

namespace dream::agents {

/// `value` as a person writes it in a config ("-0.1", "1e-07") for error
/// messages; std::to_string's six fixed decimals would print -1e-07 as
/// "-0.000000", hiding the very value that was wrong.
inline std::string NumberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace dream::agents
