#pragma once

#include <string>

#include "dream/agents/framework/robot_limits.h"

namespace dream::agents {

/// Parameters every Robot has (the thesis's Robot class).
struct RobotParams {
  double vel_gain = 0.8;  ///< single-integrator -> unicycle linear gain (> 0)
  double ang_gain = 3.0;  ///< single-integrator -> unicycle angular gain (> 0)
  RobotLimits limits;     ///< Robotarium GRITSBot limits

  bool IsValid(std::string* error) const;
};

}  // namespace dream::agents
