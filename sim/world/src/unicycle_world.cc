#include "dream/world/unicycle_world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "dream/world/unicycle_kinematics.h"
#include "field_check.h"
#include "pairwise_rules.h"
#include "steps_within.h"
#include "world_argument_check.h"

namespace dream::world {

UnicycleWorld::UnicycleWorld(const WorldParams& params, std::vector<Pose2> initial_poses,
                             const std::vector<RectangleObstacleSpec>& obstacle_specs)
    : params_(field_check::Checked("UnicycleWorld", params)),
      poses_(std::move(initial_poses)),
      velocities_(poses_.size()),
      obstacles_(RectangleObstacle::BuildAll(obstacle_specs, "UnicycleWorld", "obstacle_specs")),
      command_step_(poses_.size(), kNoCommand),
      command_hold_steps_(StepsWithin(params.time_step_s, params.command_timeout_s)),
      step_utime_(std::llround(params.time_step_s * 1e6)),
      pairwise_rules_(std::make_unique<PairwiseRules>(params, poses_.size())) {
  if (poses_.size() > static_cast<std::size_t>(std::numeric_limits<int32_t>::max() / 4)) {
    throw std::invalid_argument("UnicycleWorld: " + std::to_string(poses_.size()) +
                                " robots is more than this world supports");
  }
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    const Pose2& pose = poses_[i];
    if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
      throw std::invalid_argument("UnicycleWorld: initial_poses[" + std::to_string(i) + "] = (" +
                                  std::to_string(pose.x_m) + ", " + std::to_string(pose.y_m) + ", " +
                                  std::to_string(pose.theta_rad) + ") is not finite");
    }
  }
  // Worst case sizes, so Step() never allocates for the per-robot lists.
  events_.timed_out_robot_ids.reserve(poses_.size());
  events_.out_of_bounds_robot_ids.reserve(poses_.size());
  events_.actuator_limited_robot_ids.reserve(poses_.size());
  events_.colliding_pairs.reserve(poses_.size());
  events_.obstacle_contacts.reserve(obstacles_.empty() ? 0 : poses_.size());
}

UnicycleWorld::~UnicycleWorld() = default;
UnicycleWorld::UnicycleWorld(UnicycleWorld&&) noexcept = default;
UnicycleWorld& UnicycleWorld::operator=(UnicycleWorld&&) noexcept = default;

void UnicycleWorld::GetObstacleStates(std::vector<ObstacleState>* states) const {
  states->clear();
  for (const RectangleObstacle& obstacle : obstacles_) states->push_back(obstacle.State());
}

void UnicycleWorld::CheckRobotId(int robot_id, const char* caller) const {
  world_argument_check::CheckRobotId("UnicycleWorld", caller, robot_id, num_robots());
}

void UnicycleWorld::SetCommand(int robot_id, const UnicycleCommand& command) {
  CheckRobotId(robot_id, "SetCommand");
  world_argument_check::CheckCommandIsFinite("UnicycleWorld", robot_id, command);
  velocities_[static_cast<std::size_t>(robot_id)] = command;
  command_step_[static_cast<std::size_t>(robot_id)] = step_;
}

void UnicycleWorld::StopRobot(int robot_id) {
  CheckRobotId(robot_id, "StopRobot");
  velocities_[static_cast<std::size_t>(robot_id)] = UnicycleCommand{};
  command_step_[static_cast<std::size_t>(robot_id)] = kNoCommand;
}

void UnicycleWorld::ApplyCommandTimeouts() {
  if (command_hold_steps_ == std::numeric_limits<int64_t>::max()) return;
  for (std::size_t i = 0; i < command_step_.size(); ++i) {
    if (command_step_[i] != kNoCommand && step_ - command_step_[i] > command_hold_steps_) {
      velocities_[i] = UnicycleCommand{};
      command_step_[i] = kNoCommand;
      events_.timed_out_robot_ids.push_back(static_cast<int>(i));
    }
  }
}

void UnicycleWorld::Step() { StepRobots(nullptr); }

void UnicycleWorld::StepWithMotionTimes(const std::vector<double>& motion_time_s) {
  if (motion_time_s.size() != poses_.size()) {
    throw std::invalid_argument("UnicycleWorld::StepWithMotionTimes: " + std::to_string(motion_time_s.size()) +
                                " motion times for " + std::to_string(poses_.size()) + " robots");
  }
  for (double time_s : motion_time_s) {
    if (!(std::isfinite(time_s) && time_s >= 0.0)) {
      throw std::invalid_argument("UnicycleWorld::StepWithMotionTimes: a motion time must be finite and >= 0");
    }
  }
  StepRobots(motion_time_s.data());
}

void UnicycleWorld::StepRobots(const double* motion_time_s) {
  events_.Reset(step_);
  ApplyCommandTimeouts();

  const Arena& arena = params_.arena;
  const double dt = params_.time_step_s;
  const double wheel_radius_m = params_.wheel_radius_m;
  const double base_length_m = params_.base_length_m;
  const double max_wheel_speed_radps = params_.max_wheel_speed_radps;

  // One pass per robot: validation needs only this robot's current pose and
  // velocity (the pairwise check runs afterwards on the stored centres), so
  // the pose can be advanced in the same pass.
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    Pose2& pose = poses_[i];
    const double cos_theta = std::cos(pose.theta_rad);
    const double sin_theta = std::sin(pose.theta_rad);

    if (!arena.Contains(pose.x_m, pose.y_m)) {
      events_.out_of_bounds_robot_ids.push_back(static_cast<int>(i));
    }
    pairwise_rules_->SetCenter(i, pose, cos_theta, sin_theta);

    const WheelSpeeds wheels = UnicycleToWheelSpeeds(velocities_[i], wheel_radius_m, base_length_m);
    if (ExceedsWheelSpeedLimit(wheels, max_wheel_speed_radps)) {
      events_.actuator_limited_robot_ids.push_back(static_cast<int>(i));
    }
    const UnicycleCommand saturated =
        WheelSpeedsToUnicycle(ClipWheelSpeeds(wheels, max_wheel_speed_radps), wheel_radius_m, base_length_m);
    velocities_[i] = saturated;

    const double robot_dt = motion_time_s == nullptr ? dt : motion_time_s[i];
    const double distance_m = robot_dt * saturated.v_mps;
    pose.x_m += distance_m * cos_theta;
    pose.y_m += distance_m * sin_theta;
    const double theta_rad = pose.theta_rad + robot_dt * saturated.w_radps;
    pose.theta_rad = std::atan2(std::sin(theta_rad), std::cos(theta_rad));
  }

  pairwise_rules_->Apply(obstacles_, &events_);
  violations_.Add(events_);

  for (RectangleObstacle& obstacle : obstacles_) obstacle.Advance(dt);
  ++step_;
}

}  // namespace dream::world
