#pragma once

#include <Eigen/Core>

#include "dream/agents/framework/unicycle_command.h"

namespace dream::agents {

/// Maps a desired planar velocity (single-integrator) to a unicycle command,
/// as the Robotarium's create_si_to_uni_dynamics does:
///   v = k_v (cos th, sin th) . dxi
///   w = w_lim * atan2((-sin th, cos th) . dxi, (cos th, sin th) . dxi) / (pi/2)
/// so a 90-degree heading error turns at w_lim.
class SingleIntegratorToUnicycle {
 public:
  /// @param linear_gain k_v, must be positive.
  /// @param angular_limit_radps w_lim, must be non-negative.
  /// @throws std::invalid_argument naming the parameter otherwise.
  explicit SingleIntegratorToUnicycle(double linear_gain = 1.0, double angular_limit_radps = 3.14159265358979323846);

  UnicycleCommand Map(const Eigen::Vector2d& velocity_world_mps, double theta_rad) const;

 private:
  double linear_gain_;
  double angular_limit_radps_;
};

}  // namespace dream::agents
