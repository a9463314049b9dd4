#pragma once

#include <string>

#include "dream/world/arena.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::world {

// Everything UnicycleWorld needs to know about the testbed. Defaults are the
// Robotarium V2 values.
struct WorldParams {
  Arena arena{};
  double time_step_s = robotarium::RobotariumConstants::kTimeStepSeconds;
  double wheel_radius_m = robotarium::RobotariumConstants::kWheelRadiusMeters;
  double base_length_m = robotarium::RobotariumConstants::kBaseLengthMeters;
  double max_wheel_speed_radps = robotarium::RobotariumConstants::kMaxWheelVelocityRadps;
  double collision_diameter_m = robotarium::RobotariumConstants::kCollisionDiameterMeters;
  double collision_offset_m = robotarium::RobotariumConstants::kCollisionOffsetMeters;
  // A robot whose last command is older than this (in simulated time) stops,
  // as on the hardware. +infinity disables the rule (the official Python
  // simulator has none: it holds the last velocity forever).
  double command_timeout_s = robotarium::RobotariumConstants::kCommandTimeoutSeconds;

  // Checks every field; on failure writes a message naming the field, its
  // value and the allowed range into *error (if error is not null).
  bool IsValid(std::string* error) const;
};

}  // namespace dream::world
