#include "dream/agents/framework/robot.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "dream/agents/framework/params_check.h"

namespace dream::agents {

bool RobotParams::IsValid(std::string* error) const {
  return CheckPositive(error, "vel_gain", vel_gain) && CheckPositive(error, "ang_gain", ang_gain);
}

Robot::Robot(int id, RobotParams params) : id_(id), params_(params), actuator_limits_(params.limits) {
  std::string error;
  if (id < 0) throw std::invalid_argument("robot id must be >= 0, got " + std::to_string(id));
  if (!params_.IsValid(&error)) throw std::invalid_argument(error);
}

Drawing Robot::TakeDrawing() { return std::exchange(drawing_, Drawing()); }

void Robot::OnOdometry(const OdometryReading& reading) { odometry_ = reading; }
void Robot::OnMovement(const MovementReading& reading) { movement_ = reading; }
void Robot::OnObstacles(const ObstacleReading& reading) { obstacles_ = reading; }

std::optional<std::vector<uint8_t>> Robot::OnRadio(const std::vector<RadioMessage>& heard) {
  (void)heard;
  return std::nullopt;
}

long Robot::bad_radio_messages() const {
  long total = 0;
  for (const auto& [sender, count] : bad_radio_messages_by_sender_) total += count;
  return total;
}

void Robot::CountBadRadioMessage(const RadioMessage& message) { ++bad_radio_messages_by_sender_[message.sender_id]; }

void Robot::CountBadRadioMessage() { ++bad_radio_messages_by_sender_[kUnknownSender]; }

UnicycleCommand Robot::DxiToDxu(const Eigen::Vector2d& dxi_mps, double theta_rad, const RobotParams& params) {
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  const double v = params.vel_gain * (c * dxi_mps.x() + s * dxi_mps.y());
  const double w = params.ang_gain * std::atan2(-s * dxi_mps.x() + c * dxi_mps.y(), v) / (M_PI / 2.0);
  return {v, w};
}

}  // namespace dream::agents
