#pragma once

#include "dream/robotarium/robotarium_constants.h"

namespace dream::agents {

/// The physical limits of a Robotarium GRITSBot X, which every controller
/// must respect. Defaults are the Robotarium V2 constants.
struct RobotLimits {
  double max_linear_speed_mps = robotarium::RobotariumConstants::kMaxLinearVelocityMps;
  double wheel_radius_m = robotarium::RobotariumConstants::kWheelRadiusMeters;
  double base_length_m = robotarium::RobotariumConstants::kBaseLengthMeters;
  double max_wheel_speed_radps = robotarium::RobotariumConstants::kMaxWheelVelocityRadps;
  /// The official simulator's turn-rate limit, which uses the robot's diameter.
  double max_angular_speed_radps = robotarium::RobotariumConstants::kMaxAngularVelocityRadps;
};

}  // namespace dream::agents
