#pragma once

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dream/agents/fields/field_names.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/framework/number_text.h"
#include "dream/config/config_node.h"
#include "dream/config/name_suggestion.h"

namespace dream::kind_api {

/// Reads a params struct's fields from a config section by its one field
/// list (agents::FieldNames): a key the section has replaces the default, and
/// a value that breaks its rule fails with file, line, key and value
/// ("gain: must be > 0, got -1"). Keys the section has that are not fields are
/// left to the caller (the factory checks a kind's keys against KeysOf).
class FieldReader {
 public:
  /// `num_robots`: how many points RobotPoints fields hold.
  FieldReader(const config::ConfigNode& section, int num_robots) : section_(section), num_robots_(num_robots) {}

  template <typename T>
  void Number(const char* key, T& value, agents::FieldRule rule, const char*) {
    if (!section_.Has(key)) return;
    const config::ConfigNode node = section_.Required(key);
    const double read = node.AsDouble();
    if (!rule.Holds(read)) node.Fail("must be " + rule.Text() + ", got " + agents::NumberText(read));
    value = static_cast<T>(read);
  }
  template <typename T>
  void Whole(const char* key, T& value, agents::FieldRule rule, const char*) {
    if (!section_.Has(key)) return;
    const config::ConfigNode node = section_.Required(key);
    // An int field takes only what fits in an int: 2^32 + 40 is refused, not wrapped to 40.
    const long long read = std::is_same_v<T, int> ? node.AsInt32() : node.AsInt();
    if (!rule.Holds(static_cast<double>(read)))
      node.Fail("must be " + rule.Text(true) + ", got " + std::to_string(read));
    value = static_cast<T>(read);
  }
  void Flag(const char* key, bool& value, const char*) { value = section_.GetBool(key, value); }
  /// Read by the owner of the field list itself.
  void Custom(const char*, const char*) {}
  template <typename E>
  void Choice(const char* key, E& value, const std::vector<std::pair<const char*, E>>& names, const char* meaning) {
    if (!section_.Has(key)) return;
    const config::ConfigNode node = section_.Required(key);
    const std::string name = node.AsString();
    std::vector<std::string> allowed;
    for (const auto& [choice_name, choice] : names) {
      if (name == choice_name) {
        value = choice;
        return;
      }
      allowed.emplace_back(choice_name);
    }
    std::string list;
    for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
    node.Fail("unknown " + std::string(meaning) + " '" + name + "'" + config::DidYouMean(name, allowed) +
              "; allowed: " + list);
  }
  void Point(const char* key, Eigen::Vector2d& value, const char*) {
    if (section_.Has(key)) value = ReadPoint(section_.Required(key));
  }
  void RobotPoints(const char* key, std::vector<Eigen::Vector2d>& values, const char* what) {
    const config::ConfigNode list = section_.Required(key);
    if (!list.IsSequence() || list.size() != static_cast<size_t>(num_robots_)) {
      list.Fail("expected one [x, y] " + std::string(what) + " per robot (" + std::to_string(num_robots_) + "), got " +
                (list.IsSequence() ? std::to_string(list.size()) : std::string("no list")));
    }
    values.clear();
    for (size_t i = 0; i < list.size(); ++i) values.push_back(ReadPoint(list[i]));
  }
  template <typename Sub>
  void Section(const char* key, Sub& sub, const char*) {
    const config::ConfigNode node = section_.Optional(key);
    if (!node.IsDefined()) return;
    const std::vector<std::string> keys = agents::KeysOf<Sub>();
    std::vector<const char*> allowed;
    for (const std::string& k : keys) allowed.push_back(k.c_str());
    node.RejectUnknownKeys(allowed);
    FieldReader inner(node, num_robots_);
    sub.ListFields(inner);
  }

  /// An `[x, y]` in metres.
  static Eigen::Vector2d ReadPoint(const config::ConfigNode& node) {
    const std::vector<double> xy = node.AsDoubles();
    if (xy.size() != 2) node.Fail("expected [x, y] in metres, got " + std::to_string(xy.size()) + " numbers");
    return {xy[0], xy[1]};
  }

 private:
  const config::ConfigNode& section_;
  int num_robots_;
};

/// Reads `params`' fields from `section` (see FieldReader).
template <typename Params>
void ReadFields(const config::ConfigNode& section, int num_robots, Params* params) {
  FieldReader reader(section, num_robots);
  params->ListFields(reader);
}

}  // namespace dream::kind_api
