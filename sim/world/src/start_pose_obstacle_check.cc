#include "dream/world/start_pose_obstacle_check.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "field_check.h"

namespace dream::world {

StartPoseObstacleCheck::StartPoseObstacleCheck(const WorldParams& world,
                                               const std::vector<RectangleObstacleSpec>& obstacle_specs)
    : collision_offset_m_(field_check::Checked("StartPoseObstacleCheck", world).collision_offset_m),
      collision_radius_m_(world.collision_diameter_m / 2.0),
      obstacles_(RectangleObstacle::BuildAll(obstacle_specs, "StartPoseObstacleCheck", "obstacles")) {}

// The same expressions as UnicycleWorld::Step (and ViolationChecker::Check),
// in a library built with the same -ffp-contract=off, so the bits agree.
double StartPoseObstacleCheck::CollisionCenterX(const Pose2& pose) const {
  const double cos_theta = std::cos(pose.theta_rad);
  return pose.x_m + collision_offset_m_ * cos_theta;
}

double StartPoseObstacleCheck::CollisionCenterY(const Pose2& pose) const {
  const double sin_theta = std::sin(pose.theta_rad);
  return pose.y_m + collision_offset_m_ * sin_theta;
}

int StartPoseObstacleCheck::FirstTouchedObstacle(const Pose2& pose) const {
  if (obstacles_.empty()) return -1;
  const double center_x_m = CollisionCenterX(pose);
  const double center_y_m = CollisionCenterY(pose);
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    if (obstacles_[i].IntersectsDisc(center_x_m, center_y_m, collision_radius_m_)) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace dream::world
