#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "dream/node/heard.h"
#include "dream/node/intake_context.h"
#include "dream/node/robot_slot.h"

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
/// (robot_commands_t, every robot's command from one agent) is read by
/// lcm::CommandBatch and taken entry by entry, each as the DREAM_CMD_<id> it
/// stands for.
class CommandIntake {
 public:
  /// Told of each entry of a DREAM_CMDS message: the DREAM_CMD_<id> message
  /// it stands for (its channel and command) and how it was heard.
  using EntryHeard = std::function<void(const std::string& channel, const velocity_command_t& command, Heard heard)>;

  /// Everything `context` refers to must outlive the intake; its clock says
  /// when a command was heard.
  explicit CommandIntake(IntakeContext context);

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

  const IntakeContext context_;
  int64_t rejected_commands_ = 0;
  int64_t command_conflicts_ = 0;
};

}  // namespace dream::node
