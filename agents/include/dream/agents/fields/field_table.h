#pragma once

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dream/agents/fields/field_rule.h"
#include "dream/agents/framework/number_text.h"

namespace dream::agents {

/// The docs' key table of a params struct, from its field list (see
/// FieldNames): one Markdown row per key, `| key | default | meaning |`, the
/// default being the struct's own. config/README.md holds these rows, and a
/// test compares them with this output, so the docs cannot drift.
class FieldTable {
 public:
  explicit FieldTable(std::string prefix = "") : prefix_(std::move(prefix)) {}

  template <typename T>
  void Number(const char* key, T& value, FieldRule rule, const char* meaning) {
    Row(key, NumberText(static_cast<double>(value)), std::string(meaning) + (rule.bounded() ? ", " + rule.Text() : ""));
  }
  template <typename T>
  void Whole(const char* key, T& value, FieldRule rule, const char* meaning) {
    Row(key, std::to_string(value), std::string(meaning) + (rule.bounded() ? ", " + rule.Text(true) : ""));
  }
  void Flag(const char* key, bool& value, const char* meaning) { Row(key, value ? "true" : "false", meaning); }
  void Custom(const char* key, const char* meaning) { Row(key, "", meaning); }
  template <typename E>
  void Choice(const char* key, E& value, const std::vector<std::pair<const char*, E>>& names, const char* meaning) {
    std::string fallback, allowed;
    for (const auto& [name, choice] : names) {
      if (choice == value) fallback = name;
      allowed += (allowed.empty() ? "`" : ", `") + std::string(name) + "`";
    }
    Row(key, "`" + fallback + "`", std::string(meaning) + ": " + allowed);
  }
  void Point(const char* key, Eigen::Vector2d& value, const char* meaning) {
    Row(key, "[" + NumberText(value.x()) + ", " + NumberText(value.y()) + "]", meaning);
  }
  void RobotPoints(const char* key, std::vector<Eigen::Vector2d>&, const char* meaning) {
    Row(key, "required", "one `[x, y]` " + std::string(meaning) + " per robot, m");
  }
  template <typename Sub>
  void Section(const char* key, Sub& section, const char*) {
    FieldTable inner(prefix_ + key + ".");
    section.ListFields(inner);
    rows_ += inner.rows_;
  }

  const std::string& rows() const { return rows_; }

 private:
  void Row(const char* key, const std::string& fallback, const std::string& meaning) {
    rows_ += "| `" + prefix_ + key + "` | " + fallback + " | " + meaning + " |\n";
  }

  std::string prefix_;
  std::string rows_;
};

/// The key table rows of `Params` with its defaults.
template <typename Params>
std::string KeyTableOf() {
  Params params{};
  FieldTable table;
  params.ListFields(table);
  return table.rows();
}

}  // namespace dream::agents
