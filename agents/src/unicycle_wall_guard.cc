#include "dream/agents/geometry/unicycle_wall_guard.h"

#include <algorithm>
#include <cmath>

namespace dream::agents {

UnicycleCommand UnicycleWallGuard::Apply(const Eigen::Vector3d& pose, const UnicycleCommand& command) const {
  if (!pose.allFinite() || !std::isfinite(command.v_mps)) return command;
  const double h = params_.horizon_s;
  const double m = params_.margin_m;
  // Allowed planar velocities: a box holding zero (a robot already past the
  // margin may stop or head back in, never further out).
  const Eigen::Vector2d lo(std::min(0.0, (params_.x_min_m + m - pose.x()) / h),
                           std::min(0.0, (params_.y_min_m + m - pose.y()) / h));
  const Eigen::Vector2d hi(std::max(0.0, (params_.x_max_m - m - pose.x()) / h),
                           std::max(0.0, (params_.y_max_m - m - pose.y()) / h));
  const Eigen::Vector2d driven = command.v_mps * Eigen::Vector2d(std::cos(pose.z()), std::sin(pose.z()));
  // Largest scale in [0, 1] keeping scale * driven inside the box.
  double scale = 1.0;
  for (int k = 0; k < 2; ++k) {
    if (driven[k] < lo[k]) scale = std::min(scale, lo[k] / driven[k]);
    if (driven[k] > hi[k]) scale = std::min(scale, hi[k] / driven[k]);
  }
  return {std::max(0.0, scale) * command.v_mps, command.w_radps};
}

}  // namespace dream::agents
