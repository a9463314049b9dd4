#include "dream/world/robot_response.h"

#include <algorithm>
#include <cmath>

#include "dream/world/unicycle_kinematics.h"

namespace dream::world {
namespace {

// A wheel this slow (a rim speed of 0.3 mm/s) has stopped.
constexpr double kStoppedRadps = 0.02;

}  // namespace

RobotResponse::RobotResponse(const RealismParams& realism, const RobotTraits& traits, double wheel_radius_m,
                             double max_wheel_speed_radps)
    : lag_s_(realism.motor_lag_s),
      startup_m_(realism.motor_startup_m),
      accel_limit_radps2_(realism.wheel_accel_limit_radps2),
      dead_zone_v_mps_(realism.dead_zone_v_mps),
      dead_zone_w_radps_(realism.dead_zone_w_radps),
      axle_length_m_(realism.axle_length_m),
      wheel_radius_m_(wheel_radius_m),
      max_wheel_speed_radps_(max_wheel_speed_radps),
      traits_(traits) {}

double RobotResponse::RespondWheel(double current_radps, double target_radps, double duration_s) const {
  if (lag_s_ > 0.0 || startup_m_ > 0.0) {
    double time_constant_s = lag_s_;
    const bool spinning_up = std::abs(target_radps) > std::abs(current_radps) && target_radps * current_radps >= 0.0;
    if (spinning_up && startup_m_ > 0.0) {
      time_constant_s += startup_m_ / (std::abs(target_radps) * wheel_radius_m_);
    }
    if (time_constant_s <= 0.0) return target_radps;
    const double next_radps =
        current_radps + (target_radps - current_radps) * -std::expm1(-duration_s / time_constant_s);
    // A wheel slowing to a stop stops (the lag alone would creep forever, and
    // the drift with it).
    if (target_radps == 0.0 && std::abs(next_radps) < kStoppedRadps) return 0.0;
    return next_radps;
  }
  if (accel_limit_radps2_ > 0.0) {
    const double max_change = accel_limit_radps2_ * duration_s;
    return current_radps + std::clamp(target_radps - current_radps, -max_change, max_change);
  }
  return target_radps;
}

UnicycleCommand RobotResponse::Drive(const UnicycleCommand& target, double duration_s) {
  UnicycleCommand driven = target;
  if (std::abs(driven.v_mps) < dead_zone_v_mps_ && std::abs(driven.w_radps) < dead_zone_w_radps_) {
    driven = UnicycleCommand{};  // the motors coast
  }
  const bool wheel_dynamics = lag_s_ > 0.0 || startup_m_ > 0.0 || accel_limit_radps2_ > 0.0;
  if (wheel_dynamics) {
    const WheelSpeeds wanted =
        ClipWheelSpeeds(UnicycleToWheelSpeeds(driven, wheel_radius_m_, axle_length_m_), max_wheel_speed_radps_);
    wheels_.left_radps = RespondWheel(wheels_.left_radps, wanted.left_radps, duration_s);
    wheels_.right_radps = RespondWheel(wheels_.right_radps, wanted.right_radps, duration_s);
    driven = WheelSpeedsToUnicycle(wheels_, wheel_radius_m_, axle_length_m_);
  }
  // Without wheel dynamics the command goes on as it is: the true world
  // saturates it with the robot's axle, as the official one does.
  const bool wheels_turn = driven.v_mps != 0.0 || driven.w_radps != 0.0;
  if (traits_.linear_gain != 1.0) driven.v_mps *= traits_.linear_gain;
  if (traits_.angular_gain != 1.0) driven.w_radps *= traits_.angular_gain;
  if (wheels_turn && traits_.heading_drift_radps != 0.0) driven.w_radps += traits_.heading_drift_radps;
  return driven;
}

}  // namespace dream::world
