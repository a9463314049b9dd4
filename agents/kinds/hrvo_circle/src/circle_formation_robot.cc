#include "dream/hrvo_circle/circle_formation_robot.h"
#include "dream/agents/fields/field_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/params_check.h"

namespace dream::hrvo_circle {
namespace {

bool CheckStop(std::string* error, const CircleFormationParams& params) {
  if (params.stop_m > 0.0 && params.stop_m <= params.tolerance_m) return true;
  return agents::FailParams(error, "stop_m must be > 0 and <= tolerance_m (" + agents::NumberText(params.tolerance_m) +
                                       "), got " + agents::NumberText(params.stop_m));
}

}  // namespace

bool CircleFormationParams::IsValid(std::string* error) const {
  if (goals_m.empty()) return agents::FailParams(error, "goals_m must hold at least one point");
  for (size_t i = 0; i < goals_m.size(); ++i) {
    if (!goals_m[i].allFinite()) return agents::FailParams(error, "goals_m[" + std::to_string(i) + "] must be finite");
  }
  return agents::CheckAtLeast(error, "num_robots", num_robots, 1) && agents::CheckFields(*this, error) &&
         CheckStop(error, *this);
}

CircleFormationRobot::CircleFormationRobot(int id, const agents::RobotParams& robot_params,
                                           const agents::HrvoRobotParams& hrvo_params,
                                           const CircleFormationParams& params)
    : agents::HrvoRobot(id, robot_params, hrvo_params),
      params_(agents::CheckedParams(params)),
      progress_(params.num_robots, static_cast<int>(params.goals_m.size())) {
  if (id >= params.num_robots) {
    throw std::invalid_argument("robot id " + std::to_string(id) + " is not below num_robots " +
                                std::to_string(params.num_robots));
  }
}

std::optional<std::vector<uint8_t>> CircleFormationRobot::OnRadio(const std::vector<agents::RadioMessage>& heard) {
  for (const agents::RadioMessage& message : heard) {
    if (!progress_.Merge(message.payload)) CountBadRadioMessage(message);
  }
  progress_.Set(id(), reached_);
  // Everyone (as far as we know) has reached the point we hold: go to the next.
  const bool holding = reached_ == goal_index_ + 1;
  if (holding && reached_ < static_cast<int>(params_.goals_m.size()) && progress_.MinState() >= reached_) {
    goal_index_ = reached_;
  }
  return progress_.Encode();
}

agents::UnicycleCommand CircleFormationRobot::Update(int64_t step) {
  (void)step;
  if (!has_odometry()) return {};
  const Eigen::Vector2d delta = params_.goals_m[static_cast<size_t>(goal_index_)] - pose().head<2>();
  const double distance = delta.norm();
  Eigen::Vector2d preferred = Eigen::Vector2d::Zero();
  const bool at_goal = distance < params_.tolerance_m;
  if (at_goal && reached_ == goal_index_) ++reached_;
  if (distance < params_.stop_m) {
    holding_ = true;
  } else if (!at_goal) {
    holding_ = false;
  }
  if (!holding_) {
    // Slow down before the point: at full speed the loop delay carries the robot past it.
    const double speed = std::min(params_.max_speed_mps, params_.gain * distance);
    preferred = speed * delta / distance;
  }
  // HRVO even when holding still: a passing robot may need us to step aside.
  return DriveWithVelocity(preferred);
}

}  // namespace dream::hrvo_circle
