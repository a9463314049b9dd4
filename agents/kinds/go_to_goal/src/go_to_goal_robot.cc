#include "dream/go_to_goal/go_to_goal_robot.h"
#include "dream/agents/fields/field_check.h"

#include <cmath>

#include "dream/agents/framework/params_check.h"

namespace dream::go_to_goal {

bool GoToGoalParams::IsValid(std::string* error) const {
  if (!goal_m.allFinite()) return agents::FailParams(error, "goal must be finite");
  return agents::CheckFields(*this, error);
}

GoToGoalRobot::GoToGoalRobot(int id, const agents::RobotParams& robot_params, const GoToGoalParams& params)
    : agents::Robot(id, robot_params), params_(agents::CheckedParams(params)) {}

agents::UnicycleCommand GoToGoalRobot::Update(int64_t step) {
  (void)step;
  if (!has_odometry()) return {};
  const Eigen::Vector2d error = params_.goal_m - pose().head<2>();
  done_ = error.norm() <= params_.tolerance_m;
  if (done_) return {};
  Eigen::Vector2d velocity = params_.gain * error;
  if (velocity.norm() > params_.max_speed_mps) velocity *= params_.max_speed_mps / velocity.norm();
  return LimitActuators(si_to_uni_.Map(velocity, pose().z()));
}

}  // namespace dream::go_to_goal
