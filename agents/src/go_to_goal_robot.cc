#include "dream/agents/experiments/go_to_goal_robot.h"

#include <cmath>
#include <stdexcept>

namespace dream::agents {

bool GoToGoalParams::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!goal_m.allFinite()) return fail("goal must be finite");
  if (!(gain > 0.0) || !std::isfinite(gain)) return fail("gain must be > 0, got " + std::to_string(gain));
  if (!(max_speed_mps > 0.0 && max_speed_mps <= 0.2)) {
    return fail("max_speed_mps must be in (0, 0.2], got " + std::to_string(max_speed_mps));
  }
  if (!(tolerance_m > 0.0) || !std::isfinite(tolerance_m)) {
    return fail("tolerance_m must be > 0, got " + std::to_string(tolerance_m));
  }
  return true;
}

namespace {
const GoToGoalParams& Checked(const GoToGoalParams& params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument(error);
  return params;
}
}  // namespace

GoToGoalRobot::GoToGoalRobot(int id, const RobotParams& robot_params, const GoToGoalParams& params)
    : Robot(id, robot_params), params_(Checked(params)) {}

UnicycleCommand GoToGoalRobot::Update(int64_t step) {
  (void)step;
  if (!has_odometry()) return {};
  const Eigen::Vector2d error = params_.goal_m - pose().head<2>();
  done_ = error.norm() <= params_.tolerance_m;
  if (done_) return {};
  Eigen::Vector2d velocity = params_.gain * error;
  if (velocity.norm() > params_.max_speed_mps) velocity *= params_.max_speed_mps / velocity.norm();
  return LimitActuators(si_to_uni_.Map(velocity, pose().z()));
}

}  // namespace dream::agents
