#include "dream/node/busy_intake.h"

#include <chrono>
#include <cmath>
#include <utility>

#include "dream/lcm/channels.h"
#include "dream/lcm/run_id.h"
#include "dream/robot_busy_t.hpp"

namespace dream::node {
namespace {

double SecondsBetween(NodeClock::TimePoint from, NodeClock::TimePoint to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

BusyIntake::BusyIntake(IntakeContext context) : context_(std::move(context)) {}

Heard BusyIntake::Refuse(const std::string& channel, const std::string& reason, int64_t agent_id) {
  context_.bad_messages.Report(channel, "busy note refused: " + reason, agent_id);
  return Heard::kRefused;
}

Heard BusyIntake::Take(const std::string& channel, const robot_busy_t& busy) {
  if (busy.run_id != context_.run_id) {
    context_.other_world_seen(busy.run_id, channel);
    return Refuse(channel,
                  "it is of run " + lcm::RunIdText(busy.run_id) + ", not this run " + lcm::RunIdText(context_.run_id),
                  busy.agent_id);
  }
  const std::optional<int> id = lcm::RobotIdFromChannel(channel, lcm::kBusyChannelPrefix);
  if (!id || *id != busy.robot_id || *id >= context_.world.num_robots()) {
    return Refuse(channel,
                  "robot " + std::to_string(busy.robot_id) + " does not match its channel or this run's " +
                      std::to_string(context_.world.num_robots()) + " robots",
                  busy.agent_id);
  }
  if (busy.call_robot_id < -1 || busy.call_robot_id >= context_.world.num_robots() || !std::isfinite(busy.call_s) ||
      busy.call_s < 0) {
    return Refuse(channel,
                  "call_robot_id " + std::to_string(busy.call_robot_id) + " or call_s " + std::to_string(busy.call_s) +
                      " is not a robot of this run and a time",
                  busy.agent_id);
  }
  if (busy.step > context_.world.step()) {
    return Refuse(channel,
                  "step " + std::to_string(busy.step) + " has not been published (the world is at step " +
                      std::to_string(context_.world.step()) + ")",
                  busy.agent_id);
  }
  RobotSlot& robot = context_.robots[static_cast<size_t>(*id)];
  if (!robot.owned) {
    // Before its first answer nobody drives the robot: a host still loading
    // or setting it up holds the start (HoldsStart), unrecorded, as routine.
    if (busy.step == context_.world.step()) {
      robot.busy_step = busy.step;
      robot.busy_heard = context_.clock.now();
    }
    return Heard::kRepeat;
  }
  if (robot.owner_agent_id != busy.agent_id) {
    return Refuse(channel, "agent " + std::to_string(busy.agent_id) + " does not drive robot " + std::to_string(*id),
                  busy.agent_id);
  }
  if (busy.step < context_.world.step()) return Heard::kRepeat;  // late: that step is over
  robot.busy_heard = context_.clock.now();
  if (robot.busy_step == busy.step) return Heard::kRepeat;
  robot.busy_step = busy.step;
  return Heard::kUsed;
}

bool BusyIntake::HoldsStart(NodeClock::TimePoint now, NodeClock::TimePoint step_published) const {
  if (SecondsBetween(step_published, now) > kMaxHoldFactor * context_.options.start_timeout_s) return false;
  for (const RobotSlot& robot : context_.robots) {
    if (robot.command_step != context_.world.step() && !robot.lost && HeardBusyLately(robot, now)) return true;
  }
  return false;
}

bool BusyIntake::Holds(const RobotSlot& robot, NodeClock::TimePoint now, NodeClock::TimePoint step_published) const {
  return context_.options.mode == config::WorldMode::kLockstep && HeardBusyLately(robot, now) &&
         SecondsBetween(step_published, now) <= kMaxHoldFactor * context_.options.agent_timeout_s;
}

bool BusyIntake::HeardBusyLately(const RobotSlot& robot, NodeClock::TimePoint now) const {
  return robot.busy_step == context_.world.step() &&
         SecondsBetween(robot.busy_heard, now) <= context_.options.agent_timeout_s;
}

}  // namespace dream::node
