#include "dream/run_log/message_json.h"

#include <cstdio>
#include <optional>

#include "dream/applied_commands_t.hpp"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/run_id.h"
#include "dream/obstacles_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/lcm/wire_text.h"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::run_log {
namespace {

// What every dream message starts with (utime, step, run_id), then `fields` in their order.
template <typename Message>
nlohmann::ordered_json WithMessageStart(const Message& m, const nlohmann::ordered_json& fields) {
  nlohmann::ordered_json json = {{"utime", m.utime}, {"step", m.step}, {"run_id", lcm::RunIdText(m.run_id)}};
  for (const auto& [key, value] : fields.items()) json[key] = value;
  return json;
}

nlohmann::ordered_json ToJson(const robot_poses_t& m) {
  return WithMessageStart(
      m, {{"num_robots", m.num_robots}, {"x", m.x}, {"y", m.y}, {"theta", m.theta}, {"v", m.v}, {"w", m.w}});
}

nlohmann::ordered_json ToJson(const obstacles_t& m) {
  nlohmann::ordered_json obstacles = nlohmann::ordered_json::array();
  for (const rectangle_obstacle_t& o : m.obstacles) {
    obstacles.push_back({{"id", o.id},
                         {"center_x", o.center_x},
                         {"center_y", o.center_y},
                         {"width", o.width},
                         {"height", o.height},
                         {"vx", o.vx},
                         {"vy", o.vy}});
  }
  return WithMessageStart(m, {{"num_obstacles", m.num_obstacles}, {"obstacles", obstacles}});
}

nlohmann::ordered_json ToJson(const run_status_t& m) {
  return WithMessageStart(m, {{"state", m.state},
                              {"num_robots", m.num_robots},
                              {"boundary_errors", m.boundary_errors},
                              {"collision_errors", m.collision_errors},
                              {"actuator_errors", m.actuator_errors},
                              {"obstacle_collisions", m.obstacle_collisions},
                              {"rejected_commands", m.rejected_commands},
                              {"command_conflicts", m.command_conflicts},
                              {"num_lost", m.num_lost},
                              {"lost_robot_ids", m.lost_robot_ids},
                              {"detail", m.detail}});
}

nlohmann::ordered_json ToJson(const run_verdict_t& m) {
  return WithMessageStart(m, {{"verdict", m.verdict},
                              {"goal", m.goal},
                              {"exit_code", m.exit_code},
                              {"goal_completion_step", m.goal_completion_step},
                              {"goal_text", m.goal_text},
                              {"reasons", m.reasons}});
}

nlohmann::ordered_json ToJson(const velocity_command_t& m) {
  return WithMessageStart(
      m, {{"robot_id", m.robot_id}, {"agent_id", m.agent_id}, {"v", m.v}, {"w", m.w}, {"done", m.done != 0}});
}

std::string Hex(const std::vector<uint8_t>& bytes) {
  static const char* const kDigits = "0123456789abcdef";
  std::string text;
  text.reserve(bytes.size() * 2);
  for (uint8_t byte : bytes) {
    text += kDigits[byte >> 4];
    text += kDigits[byte & 0xf];
  }
  return text;
}

nlohmann::ordered_json ToJson(const radio_message_t& m) {
  return WithMessageStart(m, {{"sender_id", m.sender_id},
                              {"agent_id", m.agent_id},
                              {"payload_size", m.payload_size},
                              {"payload", Hex(m.payload)}});
}

nlohmann::ordered_json ToJson(const robot_busy_t& m) {
  return WithMessageStart(
      m,
      {{"robot_id", m.robot_id}, {"agent_id", m.agent_id}, {"call_robot_id", m.call_robot_id}, {"call_s", m.call_s}});
}

nlohmann::ordered_json ToJson(const robot_commands_t& m) {
  std::vector<bool> done;
  for (const int8_t d : m.done) done.push_back(d != 0);
  return WithMessageStart(m, {{"agent_id", m.agent_id},
                              {"num_commands", m.num_commands},
                              {"robot_id", m.robot_id},
                              {"v", m.v},
                              {"w", m.w},
                              {"done", done}});
}

nlohmann::ordered_json ToJson(const robot_fault_t& m) {
  return WithMessageStart(m, {{"robot_id", m.robot_id}, {"agent_id", m.agent_id}, {"detail", m.detail}});
}

nlohmann::ordered_json ToJson(const applied_commands_t& m) {
  return WithMessageStart(m, {{"num_robots", m.num_robots},
                              {"applied_agent_id", m.applied_agent_id},
                              {"commanded_v", m.commanded_v},
                              {"commanded_w", m.commanded_w},
                              {"conflicts", m.conflicts}});
}

nlohmann::ordered_json ToJson(const drawing_t& m) {
  const std::string text(m.text.begin(), m.text.end());
  return WithMessageStart(m, {{"robot_id", m.robot_id},
                              {"agent_id", m.agent_id},
                              {"clipped", m.clipped},
                              {"num_shapes", m.num_shapes},
                              {"kind", m.kind},
                              {"rgba", m.rgba},
                              {"width", m.width},
                              {"size", m.size},
                              {"fill", m.fill},
                              {"point_count", m.point_count},
                              {"text_length", m.text_length},
                              {"num_points", m.num_points},
                              {"x", m.x},
                              {"y", m.y},
                              {"num_text_bytes", m.num_text_bytes},
                              {"text", lcm::WireText::Of(text, text.size())}});
}

int64_t Fingerprint(const std::vector<uint8_t>& data) {
  uint64_t value = 0;
  for (size_t i = 0; i < 8; ++i) value = (value << 8) | data[i];  // big-endian, as LCM encodes it
  return static_cast<int64_t>(value);
}

}  // namespace

MessageJson::MessageJson(const std::vector<uint8_t>& data) {
  if (data.size() < 8) {
    problem_ = std::to_string(data.size()) + " bytes, too short for a fingerprint";
    return;  // no fingerprint: not a DREAM message, whatever its channel
  }
  const int64_t fingerprint = Fingerprint(data);
  const int size = static_cast<int>(data.size());
  bool matched = false;
  auto attempt = [&](auto message) {
    using Message = decltype(message);
    if (matched || fingerprint != Message::getHash()) return;
    matched = true;
    type_ = Message::getTypeName();
    if (std::optional<std::string> problem = lcm::DecodeProblem(data.data(), size, &message)) {
      outcome_ = Outcome::kUndecodable;
      problem_ = *problem;
      return;
    }
    outcome_ = Outcome::kDecoded;
    fields_ = ToJson(message);
  };
  attempt(robot_poses_t{});
  attempt(obstacles_t{});
  attempt(run_status_t{});
  attempt(velocity_command_t{});
  attempt(radio_message_t{});
  attempt(robot_fault_t{});
  attempt(robot_busy_t{});
  attempt(robot_commands_t{});
  attempt(applied_commands_t{});
  attempt(run_verdict_t{});
  attempt(drawing_t{});
  if (!matched) {
    char text[32];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(fingerprint));
    problem_ = std::string("fingerprint 0x") + text + " is none of the DREAM types'";
  }
}

}  // namespace dream::run_log
