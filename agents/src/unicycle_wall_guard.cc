#include "dream/agents/geometry/unicycle_wall_guard.h"

#include <algorithm>
#include <cmath>

#include "dream/agents/geometry/velocity_box.h"

namespace dream::agents {

UnicycleCommand UnicycleWallGuard::Apply(const Eigen::Vector3d& pose, const UnicycleCommand& command) const {
  if (!pose.allFinite() || !std::isfinite(command.v_mps)) return command;
  const VelocityBox box = VelocityBox::KeepingInside(params_.arena_min_m, params_.arena_max_m, pose.head<2>(),
                                                     params_.margin_m, params_.horizon_s);
  const Eigen::Vector2d driven = command.v_mps * Eigen::Vector2d(std::cos(pose.z()), std::sin(pose.z()));
  // Largest scale in [0, 1] keeping scale * driven inside the box.
  double scale = 1.0;
  for (int k = 0; k < 2; ++k) {
    if (driven[k] < box.lo[k]) scale = std::min(scale, box.lo[k] / driven[k]);
    if (driven[k] > box.hi[k]) scale = std::min(scale, box.hi[k] / driven[k]);
  }
  return {std::max(0.0, scale) * command.v_mps, command.w_radps};
}

}  // namespace dream::agents
