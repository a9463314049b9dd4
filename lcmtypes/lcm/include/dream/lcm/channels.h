#pragma once

#include <optional>
#include <string>

namespace dream::lcm {

// The channel contract between the world (simulator or bridge) and agents.
// See docs/architecture.md for who publishes what and when.

/// All robots' poses at a step; world -> agents. Published last in a step: it
/// is the trigger agents answer.
inline constexpr const char* kPosesChannel = "DREAM_POSES";
/// Virtual obstacles at a step; world -> agents, before DREAM_POSES.
inline constexpr const char* kObstaclesChannel = "DREAM_OBSTACLES";
/// Run state, violation counts, lost agents; world -> all.
inline constexpr const char* kStatusChannel = "DREAM_STATUS";
/// The commands the world applied at a step (applied_commands_t): recorded in
/// the run log by the world, never published.
inline constexpr const char* kAppliedChannel = "DREAM_APPLIED";
/// `world.start: placed`: the Robotarium's start-up drive before step 0
/// (robot_poses_t, step 1.. of the drive, utime negative: before the
/// experiment's time 0): recorded in the run log, never published, no step
/// of the experiment's.
inline constexpr const char* kStartupPosesChannel = "DREAM_STARTUP_POSES";
/// Prefix of the per-robot command channels DREAM_CMD_<id>; agent -> world.
inline constexpr const char* kCommandChannelPrefix = "DREAM_CMD_";
/// LCM regex matching every command channel.
inline constexpr const char* kCommandChannelRegex = "DREAM_CMD_.*";

/// Prefix of the per-robot radio channels DREAM_RADIO_<id>; agent -> agents.
inline constexpr const char* kRadioChannelPrefix = "DREAM_RADIO_";
inline constexpr const char* kRadioChannelRegex = "DREAM_RADIO_.*";

/// Prefix of DREAM_FAULT_<id>: an agent says a robot's controller failed
/// (robot_fault_t); agent -> world, once.
inline constexpr const char* kFaultChannelPrefix = "DREAM_FAULT_";
inline constexpr const char* kFaultChannelRegex = "DREAM_FAULT_.*";

/// "DREAM_RADIO_<robot_id>".
inline std::string RadioChannel(int robot_id) { return kRadioChannelPrefix + std::to_string(robot_id); }

/// "DREAM_CMD_<robot_id>".
inline std::string CommandChannel(int robot_id) {
  return kCommandChannelPrefix + std::to_string(robot_id);
}

/// The robot id after `prefix` in a channel name, or nothing when the suffix
/// is not a plain non-negative decimal number.
inline std::optional<int> RobotIdFromChannel(const std::string& channel, const std::string& prefix) {
  if (channel.rfind(prefix, 0) != 0 || channel.size() == prefix.size() ||
      channel.size() > prefix.size() + 6) {
    return std::nullopt;
  }
  int id = 0;
  for (size_t i = prefix.size(); i < channel.size(); ++i) {
    if (channel[i] < '0' || channel[i] > '9') return std::nullopt;
    id = id * 10 + (channel[i] - '0');
  }
  return id;
}

/// The robot id of a DREAM_CMD_<id> channel (see RobotIdFromChannel).
inline std::optional<int> RobotIdFromCommandChannel(const std::string& channel) {
  return RobotIdFromChannel(channel, kCommandChannelPrefix);
}

}  // namespace dream::lcm
