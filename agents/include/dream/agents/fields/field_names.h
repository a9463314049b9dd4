#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dream/agents/fields/field_rule.h"

namespace dream::agents {

/// The keys of a params struct, from its one field list:
///     template <typename Fields> void ListFields(Fields& fields) { fields.Number("gain", gain, ...); ... }
/// (the pattern of Drake's Serialize/DRAKE_NVP): a reader, a checker, the
/// allowed keys and the docs' key table all walk the same list, so each key is
/// written once. This visitor only collects the names.
class FieldNames {
 public:
  template <typename T>
  void Number(const char* key, T&, FieldRule, const char*) {
    names.emplace_back(key);
  }
  template <typename T>
  void Whole(const char* key, T&, FieldRule, const char*) {
    names.emplace_back(key);
  }
  void Flag(const char* key, bool&, const char*) { names.emplace_back(key); }
  template <typename E>
  void Choice(const char* key, E&, const std::vector<std::pair<const char*, E>>&, const char*) {
    names.emplace_back(key);
  }
  void Point(const char* key, Eigen::Vector2d&, const char*) { names.emplace_back(key); }
  void RobotPoints(const char* key, std::vector<Eigen::Vector2d>&, const char*) { names.emplace_back(key); }
  template <typename Sub>
  void Section(const char* key, Sub&, const char*) {
    names.emplace_back(key);
  }
  /// A key whose structure the owner reads itself (a maneuver's keyframes).
  void Custom(const char* key, const char*) { names.emplace_back(key); }

  std::vector<std::string> names;
};

/// The config keys of `Params` (a struct with ListFields), in their order.
template <typename Params>
std::vector<std::string> KeysOf() {
  Params params{};
  FieldNames names;
  params.ListFields(names);
  return names.names;
}

}  // namespace dream::agents
