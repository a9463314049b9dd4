#pragma once

#include <cstdint>
#include <string>

#include "dream/node/heard.h"
#include "dream/node/intake_context.h"
#include "dream/node/node_clock.h"
#include "dream/node/robot_slot.h"

namespace dream {
class robot_busy_t;
}

namespace dream::node {

/// SimNode's intake of DREAM_BUSY_<id>: an agent host saying that a robot's
/// answer to the current step is held up by a controller call its watchdog
/// will end. A lockstep world does not call such a robot silent while the
/// notes keep coming (each holds for agent_timeout_s), up to kMaxHoldFactor x
/// agent_timeout_s from the step: so whether a stuck call ends as the host's
/// fault or as a lost robot depends on the host's own deadline, not on which
/// of two clocks a loaded machine runs first. Only the robot's own agent may
/// say it; the first note per robot and step is recorded, the rest only
/// refresh the hold. Before the run starts the same notes hold the start.
class BusyIntake {
 public:
  /// A host still saying busy this long after the step (in agent_timeout_s)
  /// is not believed: its robot is lost as silent.
  static constexpr double kMaxHoldFactor = 10.0;

  /// Everything `context` refers to must outlive the intake.
  explicit BusyIntake(IntakeContext context);

  Heard Take(const std::string& channel, const robot_busy_t& busy);

  /// True while a host still loading or setting up a robot that has not
  /// answered the first step holds the start: it ends the load itself (its
  /// watchdog, then its kill) with the robot's fault. At most kMaxHoldFactor x
  /// start_timeout_s from the step; any agent may hold an unclaimed robot.
  bool HoldsStart(NodeClock::TimePoint now, NodeClock::TimePoint step_published) const;
  /// True while `robot`'s host holds off its being called silent at the
  /// current step, published at `step_published`.
  bool Holds(const RobotSlot& robot, NodeClock::TimePoint now, NodeClock::TimePoint step_published) const;

 private:
  Heard Refuse(const std::string& channel, const std::string& reason, int64_t agent_id);
  /// A note for the current step heard within agent_timeout_s: what any hold needs.
  bool HeardBusyLately(const RobotSlot& robot, NodeClock::TimePoint now) const;

  const IntakeContext context_;
};

}  // namespace dream::node
