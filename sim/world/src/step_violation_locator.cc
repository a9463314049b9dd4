#include "dream/world/step_violation_locator.h"

#include <cmath>

#include "dream/world/violation_checker.h"

namespace dream::world {

StepViolationLocator::StepViolationLocator(const WorldParams& world) : world_(world) {}
StepViolationLocator::~StepViolationLocator() = default;

const StepEvents& StepViolationLocator::last_step_events() const {
  static const StepEvents kNone;
  return checker_ != nullptr ? checker_->last_step_events() : kNone;
}

bool StepViolationLocator::Locate(int64_t step, int num_robots, const std::vector<double>& x,
                                  const std::vector<double>& y, const std::vector<double>& theta,
                                  const std::vector<ObstacleState>& obstacles, std::vector<LocatedViolation>* found) {
  const auto n = static_cast<size_t>(num_robots);
  if (num_robots < 1 || x.size() != n || y.size() != n || theta.size() != n) return false;
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(theta[i])) return false;
  }
  poses_.resize(n);
  for (size_t i = 0; i < n; ++i) poses_[i] = {x[i], y[i], theta[i]};
  obstacles_.clear();
  for (const ObstacleState& o : obstacles) {
    if (std::isfinite(o.center_x_m) && std::isfinite(o.center_y_m) && std::isfinite(o.width_m) &&
        std::isfinite(o.height_m)) {
      obstacles_.push_back(o);
    }
  }
  if (checker_ == nullptr || checked_robots_ != num_robots) {
    checker_ = std::make_unique<ViolationChecker>(world_, num_robots);
    checked_robots_ = num_robots;
  }
  checker_->Check(step, poses_, nullptr, obstacles_);
  PlaceViolations(checker_->last_step_events(), poses_, found);
  return true;
}

void PlaceViolations(const StepEvents& events, const std::vector<Pose2>& poses, std::vector<LocatedViolation>* found) {
  const int n = static_cast<int>(poses.size());
  auto known = [n](int robot) { return robot >= 0 && robot < n; };
  auto add = [&](LocatedViolation::Kind kind, int robot, int other, double x_m, double y_m) {
    found->push_back({kind, robot, other, events.step, events.step, x_m, y_m});
  };
  for (const int robot : events.out_of_bounds_robot_ids) {
    if (known(robot)) add(LocatedViolation::Kind::kBoundary, robot, -1, poses[robot].x_m, poses[robot].y_m);
  }
  for (const StepEvents::RobotPair& pair : events.colliding_pairs) {
    if (!known(pair.first_robot_id) || !known(pair.second_robot_id)) continue;
    const Pose2& a = poses[static_cast<size_t>(pair.first_robot_id)];
    const Pose2& b = poses[static_cast<size_t>(pair.second_robot_id)];
    add(LocatedViolation::Kind::kCollision, pair.first_robot_id, pair.second_robot_id, (a.x_m + b.x_m) / 2,
        (a.y_m + b.y_m) / 2);
  }
  for (const StepEvents::RobotObstacleContact& contact : events.obstacle_contacts) {
    if (!known(contact.robot_id)) continue;
    const Pose2& at = poses[static_cast<size_t>(contact.robot_id)];
    add(LocatedViolation::Kind::kObstacle, contact.robot_id, contact.obstacle_id, at.x_m, at.y_m);
  }
}

}  // namespace dream::world
