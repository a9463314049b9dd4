#include "dream/barriers/unicycle_barrier.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dream::barriers {
namespace {

UnicycleBarrierParams Checked(UnicycleBarrierParams params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument("unicycle barrier: " + error);
  return params;
}

SingleIntegratorBarrierParams ProjectedPointParams(const UnicycleBarrierParams& params) {
  SingleIntegratorBarrierParams projected;
  projected.safety_radius_m = params.safety_radius_m + 2 * params.projection_distance_m;
  projected.barrier_gain = params.barrier_gain;
  projected.magnitude_limit_mps = params.magnitude_limit_mps;
  projected.boundary = params.boundary;
  return projected;
}

}  // namespace

UnicycleBarrier::UnicycleBarrier(UnicycleBarrierParams params)
    : params_(Checked(params)), single_integrator_(ProjectedPointParams(params_)) {}

BarrierResult UnicycleBarrier::Apply(const Eigen::Matrix2Xd& commands, const Eigen::Matrix3Xd& poses,
                                     const Eigen::Matrix2Xd& obstacle_points) {
  const int n = static_cast<int>(commands.cols());
  const int obstacles = static_cast<int>(obstacle_points.cols());
  if (poses.cols() != n) {
    throw std::invalid_argument("unicycle barrier: " + std::to_string(n) + " commands for " +
                                std::to_string(poses.cols()) + " poses");
  }
  BarrierResult result;
  result.commands = commands;
  if (n < 2) return result;
  if (n + obstacles > SingleIntegratorBarrier::kMaxPoints) {
    throw std::invalid_argument("unicycle barrier: " + std::to_string(n) + " robots and " + std::to_string(obstacles) +
                                " obstacle points, at most " + std::to_string(SingleIntegratorBarrier::kMaxPoints) +
                                " in all");
  }
  const double d = params_.projection_distance_m;
  Eigen::Matrix2Xd points(2, n + obstacles);
  Eigen::Matrix2Xd velocities = Eigen::Matrix2Xd::Zero(2, n + obstacles);
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(poses(2, i));
    const double s = std::sin(poses(2, i));
    points(0, i) = poses(0, i) + d * c;
    points(1, i) = poses(1, i) + d * s;
    // The projected point's velocity: R(theta) diag(1, d) (v, w).
    velocities(0, i) = c * commands(0, i) + (-s * d) * commands(1, i);
    velocities(1, i) = s * commands(0, i) + (c * d) * commands(1, i);
  }
  points.rightCols(obstacles) = obstacle_points;
  const BarrierResult safe = single_integrator_.Apply(velocities, points);
  result.qp_iterations = safe.qp_iterations;
  if (safe.qp_failed) {
    result.qp_failed = true;
    result.commands.setZero();
    return result;
  }
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(poses(2, i));
    const double s = std::sin(poses(2, i));
    // Back to (v, w): diag(1, 1/d) R(theta)'.
    result.commands(0, i) = c * safe.commands(0, i) + s * safe.commands(1, i);
    result.commands(1, i) = (-s * (1 / d)) * safe.commands(0, i) + (c * (1 / d)) * safe.commands(1, i);
  }
  return result;
}

}  // namespace dream::barriers
