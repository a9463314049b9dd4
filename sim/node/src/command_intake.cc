#include "dream/node/command_intake.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <utility>

#include "dream/lcm/channels.h"
#include "dream/lcm/command_batch.h"
#include "dream/lcm/run_id.h"
#include "dream/robot_commands_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::node {
namespace {

// Bit for bit, so a resent NaN command is the same command (and not a conflict).
bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

}  // namespace

CommandIntake::CommandIntake(IntakeContext context) : context_(std::move(context)) {}

void CommandIntake::Reject(const std::string& channel, const std::string& reason, int64_t agent_id) {
  ++rejected_commands_;
  // Rejections are the user's bug; say it once per channel, then every 100th.
  context_.bad_messages.Report(channel, "rejected command: " + reason, agent_id);
}

void CommandIntake::Conflict(const std::string& channel, RobotSlot& robot, const velocity_command_t& command,
                             const std::string& reason) {
  ++command_conflicts_;
  ++robot.conflicts;
  Reject(channel, "conflict: " + reason, command.agent_id);
}

Heard CommandIntake::Take(const std::string& channel, const velocity_command_t& command) {
  return TakeFor(channel, lcm::RobotIdFromCommandChannel(channel), command);
}

Heard CommandIntake::TakeAll(const std::string& channel, const robot_commands_t& commands, const EntryHeard& each) {
  const lcm::CommandBatch batch(commands, context_.world.num_robots());
  if (batch.problem()) {
    Reject(channel, *batch.problem() + ": the whole message is refused", commands.agent_id);
    return Heard::kRefused;
  }
  for (size_t i = 0; i < batch.size(); ++i) {
    const velocity_command_t command = batch.Entry(i);
    const Heard heard = TakeFor(channel + " robot " + std::to_string(command.robot_id), command.robot_id, command);
    each(lcm::CommandChannel(command.robot_id), command, heard);
  }
  return Heard::kUsed;
}

Heard CommandIntake::TakeFor(const std::string& channel, std::optional<int> channel_id,
                             const velocity_command_t& command) {
  const std::optional<int> id = AddressedRobot(channel, channel_id, command);
  if (!id) return Heard::kRefused;
  const bool lockstep = context_.options.mode == config::WorldMode::kLockstep;
  RobotSlot& robot = context_.robots[static_cast<size_t>(*id)];
  // Late (older than the command held, or for a step the robot missed) or
  // resent: not used again, so not recorded again; the log keeps one command
  // per robot and step, whoever floods the bus.
  if (command.step < robot.command_step) return Heard::kRepeat;
  if (command.step == robot.command_step) return AgainForHeldStep(channel, *id, robot, command);
  if (lockstep && command.step < context_.world.step()) return Heard::kRepeat;
  if (!ClaimRobot(channel, *id, robot, command)) return Heard::kRefused;
  return Hold(channel, *id, robot, command);
}

std::optional<int> CommandIntake::AddressedRobot(const std::string& channel, std::optional<int> channel_id,
                                                 const velocity_command_t& command) {
  if (!channel_id) {
    Reject(channel, "channel name must be DREAM_CMD_<robot id>", command.agent_id);
    return std::nullopt;
  }
  if (command.run_id != context_.run_id) {
    context_.other_world_seen(command.run_id, channel);
    Reject(channel,
           "answers run " + lcm::RunIdText(command.run_id) + ", not this run " + lcm::RunIdText(context_.run_id),
           command.agent_id);
    return std::nullopt;
  }
  const int id = *channel_id;
  if (id < 0 || id >= context_.world.num_robots()) {
    Reject(channel,
           "robot " + std::to_string(id) + " does not exist: this run has " +
               std::to_string(context_.world.num_robots()) + " robots (ids 0.." +
               std::to_string(context_.world.num_robots() - 1) + ")",
           command.agent_id);
    return std::nullopt;
  }
  if (command.robot_id != id) {
    Reject(channel, "payload robot_id " + std::to_string(command.robot_id) + " does not match the channel",
           command.agent_id);
    return std::nullopt;
  }
  // Commands answer the step the world is at: a later step was never
  // published, and one further back is late (lockstep: already taken).
  if (command.step < 0 || command.step > context_.world.step()) {
    Reject(channel,
           "answers step " + std::to_string(command.step) + " but the world is at step " +
               std::to_string(context_.world.step()),
           command.agent_id);
    return std::nullopt;
  }
  return id;
}

Heard CommandIntake::AgainForHeldStep(const std::string& channel, int id, RobotSlot& robot,
                                      const velocity_command_t& command) {
  // The resend of the world's step gets the same answer again; anything
  // else for this robot and step is a second sender, also when it comes
  // just after the world took the step (the held command is that step's).
  // The held command came from the robot's owner (others are refused).
  const bool same = SameBits(command.v, robot.received_v) && SameBits(command.w, robot.received_w) &&
                    command.done == robot.done && command.agent_id == robot.owner_agent_id;
  if (!same) {
    Conflict(channel, robot, command,
             "robot " + std::to_string(id) + " already has a different command for step " +
                 std::to_string(command.step) + " (from agent " + std::to_string(robot.owner_agent_id) +
                 "); this one from agent " + std::to_string(command.agent_id) + " is refused, the first is applied");
    return Heard::kRefused;
  }
  return Heard::kRepeat;  // the same again (the world resent its step)
}

bool CommandIntake::ClaimRobot(const std::string& channel, int id, RobotSlot& robot,
                               const velocity_command_t& command) {
  if (!robot.owned || (robot.lost && robot.owner_agent_id != command.agent_id)) {
    if (robot.owned)
      spdlog::warn("robot {}: agent {:#x} takes over from lost agent {:#x}", id, command.agent_id,
                   robot.owner_agent_id);
    robot.owned = true;
    robot.owner_agent_id = command.agent_id;
  } else if (robot.owner_agent_id != command.agent_id) {
    Conflict(channel, robot, command,
             "robot " + std::to_string(id) + " is already driven by agent " + std::to_string(robot.owner_agent_id) +
                 "; a second agent " + std::to_string(command.agent_id) +
                 " sends commands for it too. Stop one of them.");
    return false;
  }
  return true;
}

Heard CommandIntake::Hold(const std::string& channel, int id, RobotSlot& robot, const velocity_command_t& command) {
  robot.last_heard = context_.clock.now();
  if (robot.lost) {
    robot.lost = false;
    spdlog::info("robot {}: agent is back (step {})", id, context_.world.step());
  }

  robot.command_step = command.step;
  robot.conflicts = 0;
  robot.received_v = command.v;
  robot.received_w = command.w;
  const bool finite = std::isfinite(command.v) && std::isfinite(command.w);
  const bool absurd = !finite || std::abs(command.v) > context_.options.max_abs_v_mps ||
                      std::abs(command.w) > context_.options.max_abs_w_radps;
  if (absurd) {
    Reject(channel,
           "absurd velocity v=" + std::to_string(command.v) + " m/s, w=" + std::to_string(command.w) +
               " rad/s (limits " + std::to_string(context_.options.max_abs_v_mps) + ", " +
               std::to_string(context_.options.max_abs_w_radps) + "); robot " + std::to_string(id) + " holds still",
           command.agent_id);
    robot.v_mps = 0.0;
    robot.w_radps = 0.0;
  } else {
    robot.v_mps = command.v;
    robot.w_radps = command.w;
  }
  robot.done = command.done;
  if (context_.options.mode != config::WorldMode::kLockstep)
    context_.world.SetCommand(id, world::UnicycleCommand{robot.v_mps, robot.w_radps});
  // An absurd command answers the step (the robot holds still), but its
  // values were refused: kept apart from the log, whose DREAM_APPLIED shows the stop.
  return absurd ? Heard::kRefused : Heard::kUsed;
}

}  // namespace dream::node
