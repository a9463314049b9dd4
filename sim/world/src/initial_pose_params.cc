#include "dream/world/initial_pose_params.h"

#include <cmath>

#include "field_check.h"

namespace dream::world {

using field_check::Fail;

bool InitialPoseParams::IsValid(std::string* error) const {
  if (!field_check::IsPositiveFinite(min_spacing_m)) {
    return Fail(error, "initial_poses.generate.min_spacing_m", min_spacing_m, "> 0 m, finite");
  }
  if (!std::isfinite(wall_margin_m) || wall_margin_m < 0.0) {
    return Fail(error, "initial_poses.generate.wall_margin_m", wall_margin_m, ">= 0 m, finite");
  }
  if (max_attempts_per_robot < 1 || max_attempts_per_robot > 1000000) {
    return Fail(error, "initial_poses.max_attempts_per_robot", max_attempts_per_robot, "[1, 1000000]");
  }
  return true;
}

}  // namespace dream::world
