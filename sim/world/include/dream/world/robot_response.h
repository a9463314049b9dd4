#pragma once

#include "dream/world/realism_params.h"
#include "dream/world/robot_traits.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/wheel_speeds.h"

namespace dream::world {

// What one robot's firmware and motors make of the command it follows (steps
// 3-5 of RealisticWorld::Step): the dead zone, wheel speeds with the robot's
// axle clipped to the official limit, each wheel's response (a first-order
// lag, slower when spinning up towards a slow speed, or an acceleration
// limit), then the robot's own gains and heading drift. `dream calibrate`
// runs this same class on a lab run's commands to fit its keys, so the world
// and the fit can never disagree on the model.
class RobotResponse {
 public:
  RobotResponse(const RealismParams& realism, const RobotTraits& traits, double wheel_radius_m,
                double max_wheel_speed_radps);

  // The velocity the robot drives over the next `duration_s`, given the
  // command its firmware follows.
  UnicycleCommand Drive(const UnicycleCommand& target, double duration_s);
  // Braked: the wheels stop at once.
  void Stop() { wheels_ = WheelSpeeds{}; }

  const WheelSpeeds& wheels() const { return wheels_; }
  const RobotTraits& traits() const { return traits_; }

 private:
  double RespondWheel(double current_radps, double target_radps, double duration_s) const;

  double lag_s_;
  double startup_m_;
  double accel_limit_radps2_;
  double dead_zone_v_mps_;
  double dead_zone_w_radps_;
  double axle_length_m_;
  double wheel_radius_m_;
  double max_wheel_speed_radps_;
  RobotTraits traits_;
  WheelSpeeds wheels_;
};

}  // namespace dream::world
