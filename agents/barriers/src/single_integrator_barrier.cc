#include "dream/barriers/single_integrator_barrier.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dream::barriers {
namespace {

/// The eight sides of the speed octagon, in rps's order.
constexpr double kDiagonal = 0.70710678118654752440;  // 1/sqrt(2)
constexpr double kOctagonSides[8][2] = {{1, 0},  {kDiagonal, kDiagonal},   {0, 1},  {-kDiagonal, kDiagonal},
                                        {-1, 0}, {-kDiagonal, -kDiagonal}, {0, -1}, {kDiagonal, -kDiagonal}};
/// The walls' rate is this fraction of the pairs' gain in rps.
constexpr double kWallGainFraction = 0.4;

SingleIntegratorBarrierParams Checked(SingleIntegratorBarrierParams params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument("single-integrator barrier: " + error);
  return params;
}

}  // namespace

SingleIntegratorBarrier::SingleIntegratorBarrier(SingleIntegratorBarrierParams params)
    : params_(Checked(params)), solver_(QpSettings::Robotarium()) {}

void SingleIntegratorBarrier::BuildConstraints(const Eigen::Matrix2Xd& positions) {
  const int n = static_cast<int>(positions.cols());
  const double radius = params_.safety_radius_m;
  const double gain = params_.barrier_gain;
  constraints_.Reset(n);
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double dx = positions(0, i) - positions(0, j);
      const double dy = positions(1, i) - positions(1, j);
      const double h = dx * dx + dy * dy - radius * radius;
      constraints_.AddRow(i, -2 * dx, -2 * dy, j, 2 * dx, 2 * dy, gain * std::pow(h, 3));
    }
  }
  if (params_.boundary) {
    const BoundaryBox& b = *params_.boundary;
    const double wall_gain = kWallGainFraction * gain;
    for (int k = 0; k < n; ++k) {
      const double x = positions(0, k);
      const double y = positions(1, k);
      constraints_.AddRow(k, 0.0, 1.0, wall_gain * std::pow(b.y_max_m - radius / 2 - y, 3));
      constraints_.AddRow(k, 0.0, -1.0, wall_gain * std::pow(y - b.y_min_m - radius / 2, 3));
      constraints_.AddRow(k, 1.0, 0.0, wall_gain * std::pow(b.x_max_m - radius / 2 - x, 3));
      constraints_.AddRow(k, -1.0, 0.0, wall_gain * std::pow(x - b.x_min_m - radius / 2, 3));
    }
  }
  const double side_bound = params_.magnitude_limit_mps * std::cos(M_PI / 8);
  for (int k = 0; k < n; ++k) {
    for (int side = 0; side < 8; ++side) {
      // rps's certificate without boundary bounds its first side by the limit itself.
      const double bound = (side == 0 && !params_.boundary) ? params_.magnitude_limit_mps : side_bound;
      constraints_.AddRow(k, kOctagonSides[side][0], kOctagonSides[side][1], bound);
    }
  }
}

BarrierResult SingleIntegratorBarrier::Apply(const Eigen::Matrix2Xd& velocities, const Eigen::Matrix2Xd& positions) {
  const int n = static_cast<int>(velocities.cols());
  if (positions.cols() != n) {
    throw std::invalid_argument("single-integrator barrier: " + std::to_string(n) + " velocities for " +
                                std::to_string(positions.cols()) + " positions");
  }
  if (n > kMaxPoints) {
    throw std::invalid_argument("single-integrator barrier: " + std::to_string(n) + " points, at most " +
                                std::to_string(kMaxPoints));
  }
  BarrierResult result;
  result.commands = velocities;
  if (n < 2) return result;
  BuildConstraints(positions);
  const Eigen::VectorXd p = Eigen::VectorXd::Constant(2 * n, 2.0);
  const Eigen::VectorXd q = -2.0 * Eigen::Map<const Eigen::VectorXd>(velocities.data(), 2 * n);
  const QpSolution solution = solver_.Solve(p, q, constraints_);
  result.qp_iterations = solution.iterations;
  if (solution.status != QpStatus::kOptimal) {
    result.qp_failed = true;
    result.commands.setZero();
    return result;
  }
  result.commands = Eigen::Map<const Eigen::Matrix2Xd>(solution.x.data(), 2, n);
  return result;
}

}  // namespace dream::barriers
