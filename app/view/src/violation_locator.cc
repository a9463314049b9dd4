#include "dream/view/violation_locator.h"

#include "dream/render/run_geometry.h"

namespace dream::view {

const char* ViolationKindName(ViolationMark::Kind kind) { return world::LocatedViolationKindName(kind); }

void ViolationLocator::Locate(const robot_poses_t& poses, const obstacles_t& obstacles,
                              std::vector<ViolationMark>* marks) {
  render::ObstacleStatesOf(obstacles, &boxes_);
  found_.clear();
  locator_.Locate(poses.step, poses.num_robots, poses.x, poses.y, poses.theta, boxes_, &found_);
  for (const world::LocatedViolation& v : found_) {
    marks->push_back({v.kind, poses.step, v.robot, v.other, v.x_m, v.y_m, v.worst_m});
  }
}

}  // namespace dream::view
