#include "dream/world/violation_checker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dream/world/unicycle_kinematics.h"
#include "field_check.h"
#include "pairwise_rules.h"

namespace dream::world {

ViolationChecker::ViolationChecker(const WorldParams& params, int num_robots)
    : params_(field_check::Checked("ViolationChecker", params)),
      num_robots_(static_cast<std::size_t>(std::max(num_robots, 0))),
      rules_(std::make_unique<PairwiseRules>(params, num_robots_)) {
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
  for (std::size_t i = 0; i < num_robots_; ++i) {
    const Pose2& pose = poses[i];
    if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
      throw std::invalid_argument("ViolationChecker::Check: step " + std::to_string(step) + ": robot " +
                                  std::to_string(i) + " has a pose that is not finite");
    }
    if (!params_.arena.Contains(pose.x_m, pose.y_m)) events_.out_of_bounds_robot_ids.push_back(static_cast<int>(i));
    rules_->SetCenter(i, pose, std::cos(pose.theta_rad), std::sin(pose.theta_rad));
    if (commands != nullptr) {
      const WheelSpeeds wheels = UnicycleToWheelSpeeds((*commands)[i], params_.wheel_radius_m, params_.base_length_m);
      if (ExceedsWheelSpeedLimit(wheels, params_.max_wheel_speed_radps)) {
        events_.actuator_limited_robot_ids.push_back(static_cast<int>(i));
      }
    }
  }
  rules_->Apply(obstacles, &events_);
  counts_.Add(events_);
}

}  // namespace dream::world
