#include "dream/run_log/message_difference.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "dream/run_log/message_json.h"

namespace dream::run_log {
namespace {

// Values are cut short: a radio payload's hex can be long.
std::string Shown(const nlohmann::ordered_json& value) {
  const std::string text = value.dump();
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

// The id of the robot a message is about, when it is about one.
std::string RobotOf(const nlohmann::ordered_json& fields) {
  for (const char* key : {"robot_id", "sender_id"}) {
    if (fields.contains(key)) return "robot " + fields[key].dump();
  }
  return "";
}

std::string WithPlace(const nlohmann::ordered_json& fields, const std::string& robot, const std::string& what) {
  std::string place = fields.contains("step") ? "step " + fields["step"].dump() : "";
  if (!robot.empty()) place += (place.empty() ? "" : ", ") + robot;
  return place.empty() ? what : place + ": " + what;
}

std::string ByteDifference(const std::vector<uint8_t>& first, const std::vector<uint8_t>& second) {
  const size_t n = std::min(first.size(), second.size());
  size_t i = 0;
  while (i < n && first[i] == second[i]) ++i;
  if (i == n) return std::to_string(first.size()) + " bytes vs " + std::to_string(second.size());
  return "byte " + std::to_string(i) + " differs (" + std::to_string(first[i]) + " vs " + std::to_string(second[i]) +
         ")";
}

}  // namespace

std::string FirstDifference(const std::vector<uint8_t>& first, const std::vector<uint8_t>& second) {
  const MessageJson a(first);
  const MessageJson b(second);
  if (a.outcome() != MessageJson::Outcome::kDecoded || b.outcome() != MessageJson::Outcome::kDecoded) {
    return ByteDifference(first, second);
  }
  if (a.type() != b.type()) return "a " + a.type() + " vs a " + b.type();
  const nlohmann::ordered_json& fa = a.fields();
  const nlohmann::ordered_json& fb = b.fields();
  for (const auto& [key, value] : fa.items()) {
    const nlohmann::ordered_json& other = fb[key];
    if (value == other) continue;
    // Per-robot arrays (x, y, theta of the poses): the index is the robot.
    if (value.is_array() && other.is_array()) {
      const size_t n = std::min(value.size(), other.size());
      for (size_t i = 0; i < n; ++i) {
        if (value[i] == other[i]) continue;
        return WithPlace(fa, "robot " + std::to_string(i), key + " " + Shown(value[i]) + " vs " + Shown(other[i]));
      }
      return WithPlace(fa, RobotOf(fa),
                       key + " has " + std::to_string(value.size()) + " items vs " + std::to_string(other.size()));
    }
    return WithPlace(fa, RobotOf(fa), key + " " + Shown(value) + " vs " + Shown(other));
  }
  return ByteDifference(first, second);
}

}  // namespace dream::run_log
