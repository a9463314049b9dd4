#pragma once

#include <optional>
#include <string>
#include <utility>

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
/// The one judge's verdict of a run (run_verdict_t); world -> all, once,
/// after summary.json is written, and the last event of the run's log.
inline constexpr const char* kVerdictChannel = "DREAM_VERDICT";
/// The commands the world applied at a step (applied_commands_t): recorded in
/// the run log by the world, never published.
inline constexpr const char* kAppliedChannel = "DREAM_APPLIED";
/// `world.start: placed`: the Robotarium's start-up drive before step 0
/// (robot_poses_t, step 1.. of the drive, utime negative: before the
/// experiment's time 0): recorded in the run log, never published, no step
/// of the experiment's.
inline constexpr const char* kStartupPosesChannel = "DREAM_STARTUP_POSES";
/// With world.realism on: what the agents were sent on DREAM_POSES (measured:
/// noisy, delayed), recorded just before the step's true DREAM_POSES; never
/// published.
inline constexpr const char* kMeasuredPosesChannel = "DREAM_MEASURED_POSES";
/// Prefix of the per-robot command channels DREAM_CMD_<id>; agent -> world.
inline constexpr const char* kCommandChannelPrefix = "DREAM_CMD_";
/// Every robot's command from one agent that drives them all (robot_commands_t,
/// a `dream run` script); agent -> world, which records each entry it takes as
/// its robot's DREAM_CMD_<id> (this channel never reaches a run log).
inline constexpr const char* kCommandsChannel = "DREAM_CMDS";
/// LCM regex matching every per-robot command channel.
inline constexpr const char* kCommandChannelRegex = "DREAM_CMD_.*";

/// Prefix of the per-robot radio channels DREAM_RADIO_<id>; agent -> agents.
inline constexpr const char* kRadioChannelPrefix = "DREAM_RADIO_";
inline constexpr const char* kRadioChannelRegex = "DREAM_RADIO_.*";

/// Prefix of DREAM_FAULT_<id>: an agent says a robot's controller failed
/// (robot_fault_t); agent -> world, once.
inline constexpr const char* kFaultChannelPrefix = "DREAM_FAULT_";
inline constexpr const char* kFaultChannelRegex = "DREAM_FAULT_.*";

/// Prefix of DREAM_DRAW_<id>: what a robot's controller drew (drawing_t);
/// agent -> world (recorded) and viewers, when the drawing changed.
inline constexpr const char* kDrawChannelPrefix = "DREAM_DRAW_";
/// Prefix of DREAM_BUSY_<id>: an agent host says a robot's answer to the step
/// is held up by a long controller call that its watchdog will end
/// (robot_busy_t); agent -> world, repeated while it holds.
inline constexpr const char* kBusyChannelPrefix = "DREAM_BUSY_";

/// Prefix of DREAM_LAB_CMD_<id> (velocity_command_t): in a `dream lab-replay`
/// log, the command the lab executed at that step, beside the agent's; never published.
inline constexpr const char* kLabCommandChannelPrefix = "DREAM_LAB_CMD_";

/// What an agent host hears: the world's step (poses, obstacles, status) and
/// the robots' radio. (The Python host process relays exactly these.)
inline constexpr const char* kAgentInboxRegex = "DREAM_(POSES|OBSTACLES|STATUS|RADIO_[0-9]+)";
/// What an agent host may say: its robots' commands, radio, faults and drawings.
inline constexpr const char* kAgentOutboxRegex = "DREAM_(CMD|RADIO|FAULT|DRAW)_[0-9]+";
/// What a viewer of a run draws: the world's step, the measured poses a
/// realistic world records, who spoke on the radio, what the controllers
/// drew, and the run's verdict.
inline constexpr const char* kViewChannelsRegex =
    "DREAM_(POSES|MEASURED_POSES|OBSTACLES|STATUS|VERDICT|RADIO_[0-9]+|DRAW_[0-9]+)";

/// "DREAM_RADIO_<robot_id>".
inline std::string RadioChannel(int robot_id) { return kRadioChannelPrefix + std::to_string(robot_id); }

/// "DREAM_CMD_<robot_id>".
inline std::string CommandChannel(int robot_id) { return kCommandChannelPrefix + std::to_string(robot_id); }

/// "DREAM_FAULT_<robot_id>".
inline std::string FaultChannel(int robot_id) { return kFaultChannelPrefix + std::to_string(robot_id); }

/// "DREAM_DRAW_<robot_id>".
inline std::string DrawChannel(int robot_id) { return kDrawChannelPrefix + std::to_string(robot_id); }
/// "DREAM_BUSY_<robot_id>".
inline std::string BusyChannel(int robot_id) { return kBusyChannelPrefix + std::to_string(robot_id); }

/// "DREAM_LAB_CMD_<robot_id>".
inline std::string LabCommandChannel(int robot_id) { return kLabCommandChannelPrefix + std::to_string(robot_id); }

/// The robot id after `prefix` in a channel name, or nothing when the suffix
/// is not a plain non-negative decimal number.
inline std::optional<int> RobotIdFromChannel(const std::string& channel, const std::string& prefix) {
  if (channel.rfind(prefix, 0) != 0 || channel.size() == prefix.size() || channel.size() > prefix.size() + 6) {
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

/// A channel an agent host sends on (kAgentOutboxRegex), by its kind and robot.
struct AgentChannel {
  enum class Kind { kCommand, kRadio, kFault, kDraw };
  Kind kind = Kind::kCommand;
  int robot_id = 0;
};

/// `channel` as DREAM_CMD_<id>, DREAM_RADIO_<id>, DREAM_FAULT_<id> or DREAM_DRAW_<id> (an id of
/// at most 6 decimal digits), or nothing for any other name.
inline std::optional<AgentChannel> ParseAgentChannel(const std::string& channel) {
  using Kind = AgentChannel::Kind;
  for (const auto& [prefix, kind] :
       {std::pair{kCommandChannelPrefix, Kind::kCommand}, std::pair{kRadioChannelPrefix, Kind::kRadio},
        std::pair{kFaultChannelPrefix, Kind::kFault}, std::pair{kDrawChannelPrefix, Kind::kDraw}}) {
    if (const std::optional<int> id = RobotIdFromChannel(channel, prefix)) return AgentChannel{kind, *id};
  }
  return std::nullopt;
}

}  // namespace dream::lcm
