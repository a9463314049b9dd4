#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "dream/agents/unicycle_command.h"

namespace dream::agents {

/// What a controller knows at one step: only what its robot's accessories
/// report (here, odometry of its own pose).
struct ControllerInput {
  int64_t step = 0;           ///< world step index k being answered
  Eigen::Vector3d own_pose;   ///< (x m, y m, theta rad), world frame, from odometry
};

/// What a controller decides for one step.
struct ControllerOutput {
  UnicycleCommand command;  ///< already within actuator limits
  bool done = false;        ///< the robot's task is complete (the run may end when all are)
};

/// One robot's control law. Implementations are pure logic: called once per
/// step with plain values, they return plain values; time is the step index.
class Controller {
 public:
  virtual ~Controller() = default;
  virtual ControllerOutput Step(const ControllerInput& input) = 0;
};

}  // namespace dream::agents
