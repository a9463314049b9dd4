#include "dream/view/violation_locator.h"

#include <cmath>

#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/violation_checker.h"

namespace dream::view {

const char* ViolationKindName(ViolationMark::Kind kind) { return world::LocatedViolationKindName(kind); }

ViolationLocator::ViolationLocator(const world::WorldParams& world) : world_(world) {}
ViolationLocator::~ViolationLocator() = default;

void ViolationLocator::Locate(const robot_poses_t& poses, const obstacles_t& obstacles,
                              std::vector<ViolationMark>* marks) {
  const int n = poses.num_robots;
  if (n < 1 || poses.x.size() != static_cast<size_t>(n) || poses.y.size() != static_cast<size_t>(n) ||
      poses.theta.size() != static_cast<size_t>(n)) {
    return;
  }
  std::vector<world::Pose2> at(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(poses.x[i]) || !std::isfinite(poses.y[i]) || !std::isfinite(poses.theta[i])) return;
    at[i] = {poses.x[i], poses.y[i], poses.theta[i]};
  }
  std::vector<world::ObstacleState> boxes;
  boxes.reserve(obstacles.obstacles.size());
  for (const rectangle_obstacle_t& o : obstacles.obstacles) {
    if (!std::isfinite(o.center_x) || !std::isfinite(o.center_y) || !std::isfinite(o.width) ||
        !std::isfinite(o.height)) {
      continue;
    }
    boxes.push_back({o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
  }
  if (checker_ == nullptr || num_robots_ != n) {
    checker_ = std::make_unique<world::ViolationChecker>(world_, n);
    num_robots_ = n;
  }
  checker_->Check(poses.step, at, nullptr, boxes);
  const world::StepEvents& events = checker_->last_step_events();
  for (const int robot : events.out_of_bounds_robot_ids) {
    marks->push_back({ViolationMark::Kind::kBoundary, poses.step, robot, -1, at[robot].x_m, at[robot].y_m});
  }
  for (const world::StepEvents::RobotPair& pair : events.colliding_pairs) {
    const world::Pose2& a = at[pair.first_robot_id];
    const world::Pose2& b = at[pair.second_robot_id];
    marks->push_back({ViolationMark::Kind::kCollision, poses.step, pair.first_robot_id, pair.second_robot_id,
                      (a.x_m + b.x_m) / 2, (a.y_m + b.y_m) / 2});
  }
  for (const world::StepEvents::RobotObstacleContact& contact : events.obstacle_contacts) {
    marks->push_back({ViolationMark::Kind::kObstacle, poses.step, contact.robot_id, contact.obstacle_id,
                      at[contact.robot_id].x_m, at[contact.robot_id].y_m});
  }
}

}  // namespace dream::view
