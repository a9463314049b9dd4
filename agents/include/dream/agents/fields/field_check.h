#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dream/agents/fields/field_rule.h"
#include "dream/agents/framework/number_text.h"

namespace dream::agents {

/// Checks a params struct's numbers against the rules of its field list (see
/// FieldNames): the first that breaks its rule gives the error
/// "<key> must be <rule>, got <value>". Cross-field rules stay in IsValid.
class FieldCheck {
 public:
  template <typename T>
  void Number(const char* key, T& value, FieldRule rule, const char*) {
    if (error.empty() && !rule.Holds(static_cast<double>(value))) {
      error = std::string(key) + " must be " + rule.Text() + ", got " + NumberText(static_cast<double>(value));
    }
  }
  template <typename T>
  void Whole(const char* key, T& value, FieldRule rule, const char*) {
    if (error.empty() && !rule.Holds(static_cast<double>(value))) {
      error = std::string(key) + " must be " + rule.Text(true) + ", got " + std::to_string(value);
    }
  }
  void Flag(const char*, bool&, const char*) {}
  void Custom(const char*, const char*) {}
  template <typename E>
  void Choice(const char*, E&, const std::vector<std::pair<const char*, E>>&, const char*) {}
  void Point(const char* key, Eigen::Vector2d& value, const char*) {
    if (error.empty() && !value.allFinite()) error = std::string(key) + " must be finite";
  }
  void RobotPoints(const char* key, std::vector<Eigen::Vector2d>& values, const char* meaning) {
    for (Eigen::Vector2d& value : values) Point(key, value, meaning);
  }
  template <typename Sub>
  void Section(const char* key, Sub& section, const char*) {
    FieldCheck inner;
    section.ListFields(inner);
    if (error.empty() && !inner.error.empty()) error = std::string(key) + "." + inner.error;
  }

  std::string error;  ///< empty: every field keeps its rule
};

/// True when every field of `params` keeps its rule; else false with the
/// first breach in `*error` (when not null). For a params struct's IsValid.
template <typename Params>
bool CheckFields(const Params& params, std::string* error) {
  Params copy = params;  // ListFields takes its fields by reference
  FieldCheck check;
  copy.ListFields(check);
  if (check.error.empty()) return true;
  if (error != nullptr) *error = check.error;
  return false;
}

}  // namespace dream::agents
