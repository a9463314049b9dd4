#pragma once

#include <Eigen/Core>

#include "dream/barriers/barrier_result.h"
#include "dream/barriers/single_integrator_barrier.h"
#include "dream/barriers/unicycle_barrier_params.h"

namespace dream::barriers {

/// rps V2's unicycle barrier certificate, with or without boundary
/// (`create_uni_barrier_certificate[_with_boundary]`): each robot's command
/// (v, w) moves the point `projection_distance` ahead of it; those points go
/// through the single-integrator certificate with the safety radius grown by
/// twice the projection distance, and back to (v, w).
class UnicycleBarrier {
 public:
  /// @throws std::invalid_argument naming the bad parameter.
  explicit UnicycleBarrier(UnicycleBarrierParams params);

  /// `commands` is 2 x N (v m/s, w rad/s), `poses` 3 x N (x, y, theta).
  /// `obstacle_points` (2 x M, may be empty) are points the projected points
  /// keep the safety radius from, standing still (rps's `obstacles`).
  /// With fewer than two robots the commands come back unchanged, as in rps.
  /// @throws std::invalid_argument when the sizes differ or N + M > kMaxPoints.
  BarrierResult Apply(const Eigen::Matrix2Xd& commands, const Eigen::Matrix3Xd& poses,
                      const Eigen::Matrix2Xd& obstacle_points = Eigen::Matrix2Xd());

  const UnicycleBarrierParams& params() const { return params_; }

 private:
  UnicycleBarrierParams params_;
  SingleIntegratorBarrier single_integrator_;
};

}  // namespace dream::barriers
