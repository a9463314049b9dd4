#pragma once

#include <vector>

#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/view/violation_mark.h"
#include "dream/world/located_violation.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/step_violation_locator.h"
#include "dream/world/world_params.h"

namespace dream::view {

/// Finds where the Robotarium's rules were broken at one step of a message
/// (world::StepViolationLocator, the code dream render's marks come from
/// too): run on the poses of the step whose validation a DREAM_STATUS
/// counted (live), or on every step of a run log (replay).
class ViolationLocator {
 public:
  explicit ViolationLocator(const world::WorldParams& world) : locator_(world) {}

  /// The violations of `poses` among `obstacles`, appended to `marks`. Poses
  /// with a non-finite value, or no robots, are skipped (they break no rule
  /// the checker can place).
  void Locate(const robot_poses_t& poses, const obstacles_t& obstacles, std::vector<ViolationMark>* marks);

 private:
  world::StepViolationLocator locator_;
  std::vector<world::ObstacleState> boxes_;
  std::vector<world::LocatedViolation> found_;
};

}  // namespace dream::view
