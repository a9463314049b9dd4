#pragma once

#include <Eigen/Core>

#include "dream/agents/framework/unicycle_command.h"

namespace dream::agents {

/// Maps a desired planar velocity to a unicycle command that may drive
/// backwards: the robot keeps a driving direction (forward or backward),
/// turns that direction towards the desired velocity, and
///   v = k_v (cos th, sin th) . dxi          (negative: backwards)
///   w = k_w e / (pi/2),  e the signed angle from the driving direction to dxi.
/// It switches direction when dxi is more than 90 degrees + hysteresis away
/// from it, so it never turns by much more than 90 degrees, and a dxi
/// jittering around the perpendicular does not make it flip its turn at
/// every step. Driving forward it is the thesis's dxi_to_dxu; where that
/// turns the robot round first (a second of standing still each time a
/// formation that squeezes and recovers reverses direction), this backs up.
class ReversibleSiToUni {
 public:
  /// @param linear_gain k_v, > 0. @param angular_gain k_w, > 0.
  /// @param hysteresis_rad beyond 90 degrees before switching, [0, pi/2).
  /// @throws std::invalid_argument naming the parameter otherwise.
  ReversibleSiToUni(double linear_gain, double angular_gain, double hysteresis_rad = 0.35);

  /// The command for `velocity_world_mps` at heading `theta_rad`; updates
  /// the driving direction. Zero velocity: zero command.
  UnicycleCommand Map(const Eigen::Vector2d& velocity_world_mps, double theta_rad);

  bool backward() const { return backward_; }

 private:
  double linear_gain_;
  double angular_gain_;
  double hysteresis_rad_;
  bool backward_ = false;
};

}  // namespace dream::agents
