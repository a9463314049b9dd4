#pragma once

#include <string>
#include "dream/robotarium/robotarium_constants.h"

namespace dream::agents {

/// Parameters shared by every HrvoAvoidance. Defaults are the thesis's
/// Robot_hrvo values on the Robotarium.
struct HrvoParams {
  /// Combined radius of two robots, centre to centre, m: velocities that
  /// would bring the centres closer than this are unsafe. The Robotarium
  /// counts a collision at 0.135 m; the thesis keeps 0.24 for margin. (0, 10].
  double safety_radius_m = 0.24;
  /// Largest planar speed the avoidance may return, m/s. (0, 10].
  double max_speed_mps = 0.2;
  /// Refuse velocities that would leave the arena within boundary_horizon_s.
  bool check_boundaries = true;
  double x_min_m = robotarium::RobotariumConstants::kArenaXMinMeters;  ///< arena, world frame; x_min_m < x_max_m
  double x_max_m = robotarium::RobotariumConstants::kArenaXMaxMeters;
  double y_min_m = robotarium::RobotariumConstants::kArenaYMinMeters;  ///< y_min_m < y_max_m
  double y_max_m = robotarium::RobotariumConstants::kArenaYMaxMeters;
  /// position + horizon * velocity must stay strictly inside the arena (the
  /// thesis: 1 s). (0, 100] s.
  double boundary_horizon_s = 1.0;

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

}  // namespace dream::agents
