#include "dream/affine_formation/affine_leader_robot.h"
#include "dream/agents/fields/field_check.h"

#include <cmath>
#include <stdexcept>

#include "dream/affine_formation/formation_state_message.h"
#include "dream/agents/framework/params_check.h"

namespace dream::affine_formation {

bool AffineLeaderParams::IsValid(std::string* error) const {
  if (!nominal_m.allFinite()) return agents::FailParams(error, "nominal_m must be finite");
  return maneuver.IsValid(error) && agents::CheckFields(*this, error) &&
         agents::CheckPositive(error, "time_step_s", time_step_s);
}

AffineLeaderRobot::AffineLeaderRobot(int id, const agents::RobotParams& robot_params, const AffineLeaderParams& params)
    : agents::Robot(id, robot_params),
      params_(agents::CheckedParams(params)),
      maneuver_(params.maneuver),
      drive_(robot_params.vel_gain, robot_params.ang_gain) {}

void AffineLeaderRobot::OnOdometry(const agents::OdometryReading& reading) {
  agents::Robot::OnOdometry(reading);
  odometry_step_ = reading.step;
}

std::optional<std::vector<uint8_t>> AffineLeaderRobot::OnRadio(const std::vector<agents::RadioMessage>& heard) {
  (void)heard;  // a leader's radio only publishes
  if (!has_odometry()) return std::nullopt;
  // The velocity it is about to command, as the followers do (one step less of delay).
  return FormationStateMessage{id(), pose().head<2>(), Velocity(odometry_step_)}.Encode();
}

Eigen::Vector2d AffineLeaderRobot::Velocity(int64_t step) const {
  const auto s = static_cast<double>(step);
  const Eigen::Vector2d target = maneuver_.Target(params_.nominal_m, s);
  Eigen::Vector2d velocity =
      maneuver_.TargetVelocity(params_.nominal_m, s, params_.time_step_s) + params_.gain * (target - pose().head<2>());
  if (velocity.norm() > params_.max_speed_mps) velocity *= params_.max_speed_mps / velocity.norm();
  return velocity;
}

agents::UnicycleCommand AffineLeaderRobot::Update(int64_t step) {
  if (!has_odometry()) return {};
  velocity_mps_ = Velocity(step);
  if (!params_.reversible_drive) return LimitActuators(DxiToDxu(velocity_mps_));
  return LimitActuators(drive_.Map(velocity_mps_, pose().z()));
}

}  // namespace dream::affine_formation
