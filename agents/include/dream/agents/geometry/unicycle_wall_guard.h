#pragma once

#include <Eigen/Core>

#include "dream/agents/framework/unicycle_command.h"
#include "dream/agents/geometry/robotarium_arena.h"

namespace dream::agents {

/// Where a UnicycleWallGuard keeps a robot.
struct UnicycleWallGuardParams {
  /// The arena's corners, world frame (the Robotarium's).
  Eigen::Vector2d arena_min_m = RobotariumArenaMin();
  Eigen::Vector2d arena_max_m = RobotariumArenaMax();
  /// position + horizon * (planar velocity actually driven) must stay
  /// margin_m inside the arena; closer in, the robot may not move outwards. s.
  double horizon_s = 1.0;
  /// Smaller than HrvoExactTuning::wall_margin_m, so a robot HRVO keeps on
  /// its margin line still has room to straighten its heading. m.
  double margin_m = 0.02;
};

/// A unicycle drives along its heading, not along the planar velocity its
/// controller asked for: a robot sliding along a wall whose asked velocity
/// turns (say, from "right" to "left") swings its heading through "out of the
/// arena" and, once the heading is within 90 degrees of the new velocity,
/// drives forward -- over the wall. HRVO's arena check constrains only the
/// asked velocity, so it cannot see this. The guard scales the forward speed
/// down (never up, never the turn rate) until the motion actually driven,
/// v (cos theta, sin theta), obeys the same look-ahead rule as HRVO's arena
/// check: the robot keeps turning on the spot and moves once it faces
/// inwards or along the wall.
class UnicycleWallGuard {
 public:
  explicit UnicycleWallGuard(const UnicycleWallGuardParams& params = {}) : params_(params) {}

  /// `command` with |v_mps| reduced so that pose (x, y, theta) moving along
  /// its heading obeys the look-ahead rule; w_radps unchanged.
  UnicycleCommand Apply(const Eigen::Vector3d& pose, const UnicycleCommand& command) const;

  const UnicycleWallGuardParams& params() const { return params_; }

 private:
  UnicycleWallGuardParams params_;
};

}  // namespace dream::agents
