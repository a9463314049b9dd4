#include "dream/agents/experiments/affine_leader_robot.h"

#include <cmath>
#include <stdexcept>

#include "dream/agents/experiments/formation_state_message.h"

namespace dream::agents {

bool AffineLeaderParams::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!nominal_m.allFinite()) return fail("nominal_m must be finite");
  if (!maneuver.IsValid(error)) return false;
  if (!(gain > 0.0) || !std::isfinite(gain)) return fail("gain must be > 0, got " + std::to_string(gain));
  if (!(max_speed_mps > 0.0 && max_speed_mps <= 0.2)) {
    return fail("max_speed_mps must be in (0, 0.2], got " + std::to_string(max_speed_mps));
  }
  if (!(time_step_s > 0.0) || !std::isfinite(time_step_s)) {
    return fail("time_step_s must be > 0, got " + std::to_string(time_step_s));
  }
  return true;
}

namespace {
const AffineLeaderParams& Checked(const AffineLeaderParams& params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument(error);
  return params;
}
}  // namespace

AffineLeaderRobot::AffineLeaderRobot(int id, const RobotParams& robot_params, const AffineLeaderParams& params)
    : Robot(id, robot_params),
      params_(Checked(params)),
      maneuver_(params.maneuver),
      drive_(robot_params.vel_gain, robot_params.ang_gain) {}

void AffineLeaderRobot::OnOdometry(const OdometryReading& reading) {
  Robot::OnOdometry(reading);
  odometry_step_ = reading.step;
}

std::optional<std::vector<uint8_t>> AffineLeaderRobot::OnRadio(const std::vector<RadioMessage>& heard) {
  (void)heard;  // a leader's radio only publishes
  if (!has_odometry()) return std::nullopt;
  // The velocity it is about to command, as the followers do (one step less of delay).
  return FormationStateMessage{id(), pose().head<2>(), Velocity(odometry_step_)}.Encode();
}

Eigen::Vector2d AffineLeaderRobot::Velocity(int64_t step) const {
  const auto s = static_cast<double>(step);
  const Eigen::Vector2d target = maneuver_.Target(params_.nominal_m, s);
  Eigen::Vector2d velocity = maneuver_.TargetVelocity(params_.nominal_m, s, params_.time_step_s) +
                             params_.gain * (target - pose().head<2>());
  if (velocity.norm() > params_.max_speed_mps) velocity *= params_.max_speed_mps / velocity.norm();
  return velocity;
}

UnicycleCommand AffineLeaderRobot::Update(int64_t step) {
  if (!has_odometry()) return {};
  velocity_mps_ = Velocity(step);
  if (!params_.reversible_drive) return LimitActuators(DxiToDxu(velocity_mps_));
  return LimitActuators(drive_.Map(velocity_mps_, pose().z()));
}

}  // namespace dream::agents
