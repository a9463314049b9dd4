#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dream/config/sim_node_options.h"
#include "dream/lcm/bad_message_log.h"
#include "dream/node/heard.h"
#include "dream/node/node_clock.h"
#include "dream/node/robot_slot.h"
#include "dream/world/world.h"

namespace dream {
class robot_commands_t;
class velocity_command_t;
}  // namespace dream

namespace dream::node {

/// SimNode's intake of DREAM_CMD_<id>: checks each command (channel, run,
/// robot, step), settles who drives each robot, and holds the command in the
/// robot's slot for the world to apply. A command that fails a check is
/// rejected and counted (rejected_commands); a different command for a robot
/// and step that has one already, or a second agent's, is a conflict
/// (command_conflicts): the first stays. An absurd command (NaN/inf, beyond
/// the limits) answers the step, but its robot holds still. DREAM_CMDS
/// (robot_commands_t, every robot's command from one agent) is taken entry
/// by entry, each as the DREAM_CMD_<id> it stands for.
class CommandIntake {
 public:
  /// Told of each entry of a DREAM_CMDS message: the DREAM_CMD_<id> message
  /// it stands for (its channel and command) and how it was heard.
  using EntryHeard = std::function<void(const std::string& channel, const velocity_command_t& command, Heard heard)>;

  /// Called with the run id of another world a command answers, and its channel.
  using OtherWorldSeen = std::function<void(int64_t run_id, const std::string& seen_on)>;

  /// Everything given by reference must outlive the intake; `robots` has one
  /// slot per robot of `world`; `clock` says when a command was heard.
  CommandIntake(world::World& world, const config::SimNodeOptions& options, int64_t run_id,
                std::vector<RobotSlot>& robots, lcm::BadMessageLog& bad_messages, const NodeClock& clock,
                OtherWorldSeen other_world_seen);

  Heard Take(const std::string& channel, const velocity_command_t& command);
  /// Refuses the whole message (kRefused, one rejected command) when it lists
  /// more robots than the run has or a robot twice; otherwise takes each entry
  /// exactly as Take takes its robot's DREAM_CMD_<id> from the message's agent
  /// (its refusals named "<channel> robot <id>"), tells `each`, and returns kUsed.
  Heard TakeAll(const std::string& channel, const robot_commands_t& commands, const EntryHeard& each);

  int64_t rejected_commands() const { return rejected_commands_; }
  int64_t command_conflicts() const { return command_conflicts_; }

 private:
  /// Take for a command on `channel` that says it is for robot `channel_id`
  /// (nullopt: a channel name that names no robot).
  Heard TakeFor(const std::string& channel, std::optional<int> channel_id, const velocity_command_t& command);
  /// The robot `command` is for, when it answers this run's current step on
  /// its robot's channel; otherwise rejected: nullopt.
  std::optional<int> AddressedRobot(const std::string& channel, std::optional<int> channel_id,
                                    const velocity_command_t& command);
  /// Why a DREAM_CMDS message is refused as a whole, or nothing.
  std::optional<std::string> WholeMessageProblem(const robot_commands_t& commands) const;
  /// A command for the step whose command the robot holds: the resend is a
  /// repeat, anything else a conflict.
  Heard AgainForHeldStep(const std::string& channel, int id, RobotSlot& robot, const velocity_command_t& command);
  /// Gives the robot to the command's agent when it has none (or a lost one);
  /// false: another agent drives it (a conflict).
  bool ClaimRobot(const std::string& channel, int id, RobotSlot& robot, const velocity_command_t& command);
  /// Holds the command in the robot's slot (zero velocity when absurd).
  Heard Hold(const std::string& channel, int id, RobotSlot& robot, const velocity_command_t& command);
  /// Counts a command refused because the robot has another for its step
  /// (a different one, or a second agent's): the first stays. `reason` says which.
  void Conflict(const std::string& channel, RobotSlot& robot, const velocity_command_t& command,
                const std::string& reason);
  void Reject(const std::string& channel, const std::string& reason, int64_t agent_id);

  world::World& world_;
  const config::SimNodeOptions& options_;
  int64_t run_id_;
  std::vector<RobotSlot>& robots_;
  lcm::BadMessageLog& bad_messages_;
  const NodeClock& clock_;
  OtherWorldSeen other_world_seen_;
  int64_t rejected_commands_ = 0;
  int64_t command_conflicts_ = 0;
};

}  // namespace dream::node
