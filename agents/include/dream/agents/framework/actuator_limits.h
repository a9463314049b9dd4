#pragma once

#include "dream/agents/framework/robot_limits.h"
#include "dream/agents/framework/unicycle_command.h"

namespace dream::agents {

/// The thesis's actuator_limit(): clip v and w to their limits, then, if a
/// wheel would still exceed its speed limit, shrink |v| and keep w, because
/// turning matters more than speed for where the robot ends up. The result
/// never triggers the Robotarium's actuator warning.
class ActuatorLimits {
 public:
  explicit ActuatorLimits(RobotLimits limits = {});

  /// `command` made feasible for the wheels. NaN in, zero out.
  UnicycleCommand Apply(const UnicycleCommand& command) const;

  const RobotLimits& limits() const { return limits_; }

 private:
  RobotLimits limits_;
};

}  // namespace dream::agents
