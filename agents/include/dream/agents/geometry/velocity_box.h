#pragma once

#include <Eigen/Core>

namespace dream::agents {

/// Planar velocities v with lo <= v <= hi on each axis.
struct VelocityBox {
  Eigen::Vector2d lo;
  Eigen::Vector2d hi;

  /// The velocities that keep position + horizon_s * v at least margin_m
  /// inside the arena [arena_min_m, arena_max_m] (each bound moved a further
  /// inset_mps in), widened to hold zero: a robot already past the margin may
  /// stop or head back in, never further out. HRVO's arena check and the
  /// UnicycleWallGuard share this rule.
  static VelocityBox KeepingInside(const Eigen::Vector2d& arena_min_m, const Eigen::Vector2d& arena_max_m,
                                   const Eigen::Vector2d& position_m, double margin_m, double horizon_s,
                                   double inset_mps = 0.0);
};

}  // namespace dream::agents
