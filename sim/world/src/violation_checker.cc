#include "dream/world/violation_checker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "collision_grid.h"
#include "dream/world/unicycle_kinematics.h"
#include "field_check.h"

namespace dream::sim {

ViolationChecker::ViolationChecker(const WorldParams& params, int num_robots)
    : params_(field_check::Checked("ViolationChecker", params)),
      num_robots_(static_cast<std::size_t>(std::max(num_robots, 0))),
      center_x_m_(num_robots_),
      center_y_m_(num_robots_),
      grid_(std::make_unique<CollisionGrid>(num_robots_, params.collision_diameter_m, params.arena)) {
  events_.out_of_bounds_robot_ids.reserve(num_robots_);
  events_.actuator_limited_robot_ids.reserve(num_robots_);
  events_.colliding_pairs.reserve(num_robots_);
}

ViolationChecker::~ViolationChecker() = default;
ViolationChecker::ViolationChecker(ViolationChecker&&) noexcept = default;
ViolationChecker& ViolationChecker::operator=(ViolationChecker&&) noexcept = default;

void ViolationChecker::Check(int64_t step, const std::vector<Pose2>& poses,
                             const std::vector<UnicycleCommand>* commands,
                             const std::vector<ObstacleState>& obstacles) {
  if (poses.size() != num_robots_ || (commands != nullptr && commands->size() != num_robots_)) {
    throw std::invalid_argument("ViolationChecker::Check: step " + std::to_string(step) + " has " +
                                std::to_string(poses.size()) + " poses and " +
                                std::to_string(commands != nullptr ? commands->size() : num_robots_) +
                                " commands for " + std::to_string(num_robots_) + " robots");
  }
  events_.Reset(step);
  const double offset_m = params_.collision_offset_m;
  for (std::size_t i = 0; i < num_robots_; ++i) {
    const Pose2& pose = poses[i];
    if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
      throw std::invalid_argument("ViolationChecker::Check: step " + std::to_string(step) + ": robot " +
                                  std::to_string(i) + " has a pose that is not finite");
    }
    if (!params_.arena.Contains(pose.x_m, pose.y_m)) events_.out_of_bounds_robot_ids.push_back(static_cast<int>(i));
    center_x_m_[i] = pose.x_m + offset_m * std::cos(pose.theta_rad);
    center_y_m_[i] = pose.y_m + offset_m * std::sin(pose.theta_rad);
    if (commands != nullptr) {
      const WheelSpeeds wheels = UnicycleToWheelSpeeds((*commands)[i], params_.wheel_radius_m, params_.base_length_m);
      if (ExceedsWheelSpeedLimit(wheels, params_.max_wheel_speed_radps)) {
        events_.actuator_limited_robot_ids.push_back(static_cast<int>(i));
      }
    }
  }
  grid_->FindPairs(center_x_m_.data(), center_y_m_.data(), &events_.colliding_pairs);
  std::sort(events_.colliding_pairs.begin(), events_.colliding_pairs.end(),
            [](const StepEvents::RobotPair& a, const StepEvents::RobotPair& b) {
              return a.first_robot_id != b.first_robot_id ? a.first_robot_id < b.first_robot_id
                                                          : a.second_robot_id < b.second_robot_id;
            });
  const double radius_m = params_.collision_diameter_m / 2.0;
  for (std::size_t i = 0; i < num_robots_ && !obstacles.empty(); ++i) {
    for (const ObstacleState& obstacle : obstacles) {
      if (obstacle.IntersectsDisc(center_x_m_[i], center_y_m_[i], radius_m)) {
        events_.obstacle_contacts.push_back({static_cast<int>(i), obstacle.id});
      }
    }
  }
  if (!events_.out_of_bounds_robot_ids.empty()) ++counts_.boundary_errors;
  counts_.collision_errors += static_cast<int64_t>(events_.colliding_pairs.size());
  if (!events_.actuator_limited_robot_ids.empty()) ++counts_.actuator_errors;
  counts_.obstacle_collisions += static_cast<int64_t>(events_.obstacle_contacts.size());
}

}  // namespace dream::sim
