#pragma once

#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/rectangle_obstacle.h"
#include "dream/world/rectangle_obstacle_spec.h"
#include "dream/world/world_params.h"

namespace dream::world {

// Whether a robot would start inside a virtual obstacle: the test
// UnicycleWorld counts as an obstacle collision at step 0 (the collision disc,
// centre offset along the heading, against RectangleObstacle::IntersectsDisc
// with every obstacle at its starting centre). Later steps do not matter here:
// a moving obstacle whose path crosses a start pose is allowed, and the run
// counts any contact as the Robotarium would.
class StartPoseObstacleCheck {
 public:
  // Throws std::invalid_argument if world or an obstacle spec is invalid.
  StartPoseObstacleCheck(const WorldParams& world, const std::vector<RectangleObstacleSpec>& obstacle_specs);

  // Index into obstacle_specs of the first obstacle touched by the collision
  // disc of a robot at `pose` at step 0, or -1 when the pose is clear.
  int FirstTouchedObstacle(const Pose2& pose) const;

  bool has_obstacles() const { return !obstacles_.empty(); }
  double collision_radius_m() const { return collision_radius_m_; }
  // The collision disc's centre for `pose`, computed exactly as the world does.
  double CollisionCenterX(const Pose2& pose) const;
  double CollisionCenterY(const Pose2& pose) const;

 private:
  double collision_offset_m_;
  double collision_radius_m_;
  std::vector<RectangleObstacle> obstacles_;  // at step 0
};

}  // namespace dream::world
