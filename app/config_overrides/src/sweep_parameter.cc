#include "dream/config_overrides/sweep_parameter.h"

#include <algorithm>
#include <stdexcept>

namespace dream::config_overrides {
namespace {

std::string Trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Splits at commas that are not inside [], {} or quotes.
std::vector<std::string> SplitTopLevel(const std::string& text, const std::string& option) {
  std::vector<std::string> parts;
  std::string current;
  int depth = 0;
  char quote = 0;
  for (char c : text) {
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      if (--depth < 0) throw std::invalid_argument(option + ": unbalanced '" + std::string(1, c) + "'");
    } else if (c == ',' && depth == 0) {
      parts.push_back(Trim(current));
      current.clear();
      continue;
    }
    current += c;
  }
  if (quote != 0 || depth != 0) throw std::invalid_argument(option + ": unclosed quote or bracket");
  parts.push_back(Trim(current));
  return parts;
}

// `text` for a message: a control byte (a terminal would act on it) as \xHH.
std::string Shown(const std::string& text) {
  static const char kHex[] = "0123456789abcdef";
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      shown += c;
    } else {
      shown += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 0xf];
    }
  }
  return shown;
}

}  // namespace

SweepParameter SweepParameter::ParseAssignment(const std::string& text, const std::string& expected) {
  const std::string option = "--set " + Shown(text);
  const size_t equals = text.find('=');
  if (equals == std::string::npos) throw std::invalid_argument(option + ": expected " + expected);
  SweepParameter parameter;
  parameter.key = Trim(text.substr(0, equals));
  if (parameter.key.empty()) throw std::invalid_argument(option + ": the key before '=' is empty");
  // Printable ASCII only: a config's keys are names, and a control byte or
  // NUL in a new key would make the run folder's config.yaml unreadable.
  const bool printable =
      std::all_of(parameter.key.begin(), parameter.key.end(), [](char c) { return c > ' ' && c < 0x7f; });
  if (!printable || parameter.key.front() == '.' || parameter.key.back() == '.' ||
      parameter.key.find("..") != std::string::npos) {
    throw std::invalid_argument(option + ": '" + Shown(parameter.key) +
                                "' is not a dotted key like controller.sensors.0.noise_std");
  }
  parameter.values = SplitTopLevel(text.substr(equals + 1), option);
  for (const std::string& value : parameter.values) {
    if (value.empty()) throw std::invalid_argument(option + ": empty value in the list after '='");
  }
  return parameter;
}

SweepParameter SweepParameter::Parse(const std::string& text) {
  SweepParameter parameter = ParseAssignment(text, "KEY=V1,V2,... such as controller.max_speed_mps=0.1,0.2");
  const std::string option = "--set " + Shown(text);
  if (parameter.key == "seed") throw std::invalid_argument(option + ": seeds are swept with --seeds, not --set");
  if (parameter.key == "name") throw std::invalid_argument(option + ": the sweep names each run itself");
  return parameter;
}

std::string SweepParameter::ShortName() const {
  const size_t dot = key.rfind('.');
  if (dot == std::string::npos) return key;
  const std::string last = key.substr(dot + 1);
  // A bare list index says little on its own: keep the list's name with it.
  if (last.find_first_not_of("0123456789") == std::string::npos) {
    const size_t before = key.rfind('.', dot - 1);
    return before == std::string::npos ? key : key.substr(before + 1);
  }
  return last;
}

}  // namespace dream::config_overrides
