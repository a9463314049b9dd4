#pragma once

namespace dream::agents {

/// The physical limits of a Robotarium GRITSBot X, which every controller
/// must respect. Defaults are the Robotarium V2 constants (agents/ does not
/// use the world library; robot_limits_test keeps them equal to
/// sim::RobotariumConstants).
struct RobotLimits {
  double max_linear_speed_mps = 0.2;
  double wheel_radius_m = 0.016;
  double base_length_m = 0.11;
  /// Max wheel speed, rad/s (0.2 / 0.016).
  double max_wheel_speed_radps = 0.2 / 0.016;
  /// Max turn rate, rad/s: 2 (r/d)(v_max/r) with d = 0.11 m.
  double max_angular_speed_radps = 2.0 * (0.016 / 0.11) * (0.2 / 0.016);
};

}  // namespace dream::agents
