#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dream/robot_poses_t.hpp"
#include "dream/obstacles_t.hpp"
#include "dream/view/violation_mark.h"
#include "dream/world/world_params.h"

namespace dream::world {
class ViolationChecker;
}

namespace dream::view {

/// Finds where the Robotarium's rules were broken at one step, with the
/// world's own checks (world::ViolationChecker): robots outside the arena,
/// robots too close, robots overlapping an obstacle. Run on the poses of the
/// step whose validation a DREAM_STATUS counted (live), or on every step of
/// a run log (replay).
class ViolationLocator {
 public:
  explicit ViolationLocator(const world::WorldParams& world);
  ~ViolationLocator();
  ViolationLocator(const ViolationLocator&) = delete;
  ViolationLocator& operator=(const ViolationLocator&) = delete;

  /// The violations of `poses` among `obstacles`, appended to `marks`. Poses
  /// with a non-finite value, or no robots, are skipped (they break no rule
  /// the checker can place).
  void Locate(const robot_poses_t& poses, const obstacles_t& obstacles, std::vector<ViolationMark>* marks);

 private:
  world::WorldParams world_;
  int num_robots_ = 0;
  std::unique_ptr<world::ViolationChecker> checker_;  // remade when the robot count changes
};

}  // namespace dream::view
