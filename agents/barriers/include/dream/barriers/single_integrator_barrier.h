#pragma once

#include <Eigen/Core>

#include "dream/barriers/barrier_result.h"
#include "dream/barriers/interior_point_qp.h"
#include "dream/barriers/linear_inequalities.h"
#include "dream/barriers/single_integrator_barrier_params.h"

namespace dream::barriers {

/// rps V2's single-integrator barrier certificate, with or without boundary
/// (`create_si_barrier_certificate[_with_boundary]`): the velocities nearest
/// the wanted ones, (v - v_hat)^2 least, such that every pair keeps
/// d/dt(|p_i - p_j|^2 - r^2) >= -gain h^3, each wall 0.4 gain (gap - r/2)^3,
/// and each velocity inside an octagon of `magnitude_limit`; solved as rps
/// solves it (InteriorPointQp with rps's CVXOPT settings), so the commands
/// are rps's to the QP's rounding.
class SingleIntegratorBarrier {
 public:
  /// The most robots (and obstacle points) one QP takes: 256 give 2*256
  /// unknowns and 35,000 rows, far beyond the Robotarium's 50.
  static constexpr int kMaxPoints = 256;

  /// @throws std::invalid_argument naming the bad parameter.
  explicit SingleIntegratorBarrier(SingleIntegratorBarrierParams params);

  /// `velocities` and `positions` are 2 x N (m/s, m). With fewer than two
  /// robots the velocities come back unchanged, as in rps.
  /// @throws std::invalid_argument when the sizes differ or N > kMaxPoints.
  BarrierResult Apply(const Eigen::Matrix2Xd& velocities, const Eigen::Matrix2Xd& positions);

  const SingleIntegratorBarrierParams& params() const { return params_; }
  /// The last QP's constraints (tests compare them with rps's A, b).
  const LinearInequalities& constraints() const { return constraints_; }

 private:
  void BuildConstraints(const Eigen::Matrix2Xd& positions);

  SingleIntegratorBarrierParams params_;
  InteriorPointQp solver_;
  LinearInequalities constraints_;
};

}  // namespace dream::barriers
