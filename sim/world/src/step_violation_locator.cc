#include "dream/world/step_violation_locator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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
  const size_t placed_from = found->size();
  PlaceViolations(checker_->last_step_events(), poses_, found);
  for (size_t i = placed_from; i < found->size(); ++i) (*found)[i].worst_m = Measure((*found)[i]);
  return true;
}

double StepViolationLocator::Measure(const LocatedViolation& v) const {
  const auto robot = static_cast<size_t>(v.robot);
  // The Robotarium's collision centre: collision_offset_m ahead of the pose.
  auto centre = [this](size_t i) {
    const Pose2& p = poses_[i];
    return std::pair<double, double>{p.x_m + world_.collision_offset_m * std::cos(p.theta_rad),
                                     p.y_m + world_.collision_offset_m * std::sin(p.theta_rad)};
  };
  switch (v.kind) {
    case LocatedViolation::Kind::kBoundary: {
      const Pose2& p = poses_[robot];
      const Arena& a = world_.arena;
      return std::max({a.x_min_m - p.x_m, p.x_m - a.x_max_m, a.y_min_m - p.y_m, p.y_m - a.y_max_m});
    }
    case LocatedViolation::Kind::kCollision: {
      const auto [ax, ay] = centre(robot);
      const auto [bx, by] = centre(static_cast<size_t>(v.other));
      return std::hypot(ax - bx, ay - by);
    }
    case LocatedViolation::Kind::kObstacle: {
      const auto [cx, cy] = centre(robot);
      for (const ObstacleState& o : obstacles_) {
        if (o.id != v.other) continue;
        // How far the collision disc reaches into the box: its radius less the gap to the
        // box, or more, by the distance to the nearest edge, when its centre is inside.
        const double dx = std::abs(cx - o.center_x_m) - o.width_m / 2.0;
        const double dy = std::abs(cy - o.center_y_m) - o.height_m / 2.0;
        const double outside = std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
        const double inside = std::min(std::max(dx, dy), 0.0);
        return world_.collision_diameter_m / 2.0 - outside - inside;
      }
      return std::numeric_limits<double>::quiet_NaN();
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
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
