#pragma once

#include <cstdint>
#include <vector>

#include "dream/world/initial_pose_params.h"
#include "dream/world/pose2.h"
#include "dream/world/rectangle_obstacle_spec.h"
#include "dream/world/start_pose_obstacle_check.h"
#include "dream/world/world_params.h"

namespace dream::world {

// Draws collision-free random start poses inside the arena: positions
// uniform in the arena shrunk by the wall margin, at least min_spacing_m
// apart (rejection sampling on a grid), headings uniform in [-pi, pi), and
// no collision disc touching a virtual obstacle where it is at step 0 (the
// world's own test, StartPoseObstacleCheck). A candidate an obstacle refuses
// only uses up draws, so when no obstacle is in the way the poses are the
// same as without obstacles. The random stream is std::mt19937_64 turned
// into doubles by our own code, so the same seed gives the same poses on
// every platform.
class InitialPoseGenerator {
 public:
  // Throws std::invalid_argument if either parameter set or an obstacle spec
  // is invalid, or the spacing is too small for the world's collision geometry.
  InitialPoseGenerator(const WorldParams& world, const InitialPoseParams& params,
                       const std::vector<RectangleObstacleSpec>& obstacles = {});

  // Throws std::invalid_argument (saying how many robots were placed, why
  // candidates were refused and what to change) if num_robots cannot be
  // placed within the attempt budget, which bounds the time it takes.
  std::vector<Pose2> Generate(int num_robots, uint64_t seed) const;

 private:
  WorldParams world_;
  InitialPoseParams params_;
  StartPoseObstacleCheck obstacle_check_;
};

}  // namespace dream::world
