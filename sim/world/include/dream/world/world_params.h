#pragma once

#include <string>

#include "dream/world/arena.h"
#include "dream/world/robotarium_constants.h"

namespace dream::sim {

// Everything UnicycleWorld needs to know about the testbed. Defaults are the
// Robotarium V2 values.
struct WorldParams {
  Arena arena{};
  double time_step_s = RobotariumConstants::kTimeStepSeconds;
  double wheel_radius_m = RobotariumConstants::kWheelRadiusMeters;
  double base_length_m = RobotariumConstants::kBaseLengthMeters;
  double max_wheel_speed_radps = RobotariumConstants::kMaxWheelVelocityRadps;
  double collision_diameter_m = RobotariumConstants::kCollisionDiameterMeters;
  double collision_offset_m = RobotariumConstants::kCollisionOffsetMeters;
  // A robot whose last command is older than this (in simulated time) stops,
  // as on the hardware. +infinity disables the rule (the official Python
  // simulator has none: it holds the last velocity forever).
  double command_timeout_s = RobotariumConstants::kCommandTimeoutSeconds;

  // Checks every field; on failure writes a message naming the field, its
  // value and the allowed range into *error (if error is not null).
  bool IsValid(std::string* error) const;
};

}  // namespace dream::sim
