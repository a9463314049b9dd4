#pragma once

#include <cstdint>
#include <vector>

#include "dream/sim/initial_pose_params.h"
#include "dream/sim/pose2.h"
#include "dream/sim/world_params.h"

namespace dream::sim {

// Draws collision-free random start poses inside the arena: positions
// uniform in the arena shrunk by the wall margin, at least min_spacing_m
// apart (rejection sampling on a grid), headings uniform in [-pi, pi).
// The random stream is std::mt19937_64 turned into doubles by our own
// code, so the same seed gives the same poses on every platform.
class InitialPoseGenerator {
 public:
  // Throws std::invalid_argument if either parameter set is invalid or the
  // spacing is too small for the world's collision geometry.
  InitialPoseGenerator(const WorldParams& world, const InitialPoseParams& params);

  // Throws std::invalid_argument (saying how many robots were placed) if
  // num_robots cannot be placed within the attempt budget.
  std::vector<Pose2> Generate(int num_robots, uint64_t seed) const;

 private:
  WorldParams world_;
  InitialPoseParams params_;
};

}  // namespace dream::sim
