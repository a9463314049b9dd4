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

BusyIntake::BusyIntake(const world::World& world, const config::SimNodeOptions& options, int64_t run_id,
                       std::vector<RobotSlot>& robots, lcm::BadMessageLog& bad_messages, const NodeClock& clock,
                       OtherWorldSeen other_world_seen)
    : world_(world),
      options_(options),
      run_id_(run_id),
      robots_(robots),
      bad_messages_(bad_messages),
      clock_(clock),
      other_world_seen_(std::move(other_world_seen)) {}

Heard BusyIntake::Refuse(const std::string& channel, const std::string& reason, int64_t agent_id) {
  bad_messages_.Report(channel, "busy note refused: " + reason, agent_id);
  return Heard::kRefused;
}

Heard BusyIntake::Take(const std::string& channel, const robot_busy_t& busy) {
  if (busy.run_id != run_id_) {
    other_world_seen_(busy.run_id, channel);
    return Refuse(channel, "it is of run " + lcm::RunIdText(busy.run_id) + ", not this run " + lcm::RunIdText(run_id_),
                  busy.agent_id);
  }
  const std::optional<int> id = lcm::RobotIdFromChannel(channel, lcm::kBusyChannelPrefix);
  if (!id || *id != busy.robot_id || *id >= world_.num_robots()) {
    return Refuse(channel,
                  "robot " + std::to_string(busy.robot_id) + " does not match its channel or this run's " +
                      std::to_string(world_.num_robots()) + " robots",
                  busy.agent_id);
  }
  if (busy.call_robot_id < -1 || busy.call_robot_id >= world_.num_robots() || !std::isfinite(busy.call_s) ||
      busy.call_s < 0) {
    return Refuse(channel,
                  "call_robot_id " + std::to_string(busy.call_robot_id) + " or call_s " + std::to_string(busy.call_s) +
                      " is not a robot of this run and a time",
                  busy.agent_id);
  }
  if (busy.step > world_.step()) {
    return Refuse(channel,
                  "step " + std::to_string(busy.step) + " has not been published (the world is at step " +
                      std::to_string(world_.step()) + ")",
                  busy.agent_id);
  }
  RobotSlot& robot = robots_[static_cast<size_t>(*id)];
  if (!robot.owned) {
    // Before its first answer nobody drives the robot: a host still loading
    // or setting it up holds the start (HoldsStart), unrecorded, as routine.
    if (busy.step == world_.step()) {
      robot.busy_step = busy.step;
      robot.busy_heard = clock_.now();
    }
    return Heard::kRepeat;
  }
  if (robot.owner_agent_id != busy.agent_id) {
    return Refuse(channel, "agent " + std::to_string(busy.agent_id) + " does not drive robot " + std::to_string(*id),
                  busy.agent_id);
  }
  if (busy.step < world_.step()) return Heard::kRepeat;  // late: that step is over
  robot.busy_heard = clock_.now();
  if (robot.busy_step == busy.step) return Heard::kRepeat;
  robot.busy_step = busy.step;
  return Heard::kUsed;
}

bool BusyIntake::HoldsStart(NodeClock::TimePoint now, NodeClock::TimePoint step_published) const {
  if (SecondsBetween(step_published, now) > kMaxHoldFactor * options_.start_timeout_s) return false;
  for (const RobotSlot& robot : robots_) {
    if (robot.command_step != world_.step() && !robot.lost && HeardBusyLately(robot, now)) return true;
  }
  return false;
}

bool BusyIntake::Holds(const RobotSlot& robot, NodeClock::TimePoint now, NodeClock::TimePoint step_published) const {
  return options_.mode == config::WorldMode::kLockstep && HeardBusyLately(robot, now) &&
         SecondsBetween(step_published, now) <= kMaxHoldFactor * options_.agent_timeout_s;
}

bool BusyIntake::HeardBusyLately(const RobotSlot& robot, NodeClock::TimePoint now) const {
  return robot.busy_step == world_.step() && SecondsBetween(robot.busy_heard, now) <= options_.agent_timeout_s;
}

}  // namespace dream::node
