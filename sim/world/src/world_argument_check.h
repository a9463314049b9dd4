#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "dream/world/unicycle_command.h"

namespace dream::world::world_argument_check {

// The checks every World makes on a caller's robot id and command, with one
// wording; `world` and `method` name the caller ("UnicycleWorld",
// "SetCommand"). Plain C strings, joined only for a message: the checks run
// for every command of every step, which must not allocate (step_allocation_test).

// Throws std::out_of_range unless 0 <= robot_id < num_robots.
inline void CheckRobotId(const char* world, const char* method, int robot_id, int num_robots) {
  if (robot_id < 0 || robot_id >= num_robots) {
    throw std::out_of_range(std::string(world) + "::" + method + ": robot_id " + std::to_string(robot_id) +
                            " is not in [0, " + std::to_string(num_robots) + ")");
  }
}

// Throws std::invalid_argument unless both speeds are finite.
inline void CheckCommandIsFinite(const char* world, int robot_id, const UnicycleCommand& command) {
  if (!std::isfinite(command.v_mps) || !std::isfinite(command.w_radps)) {
    throw std::invalid_argument(std::string(world) + "::SetCommand: robot " + std::to_string(robot_id) +
                                " command (v_mps=" + std::to_string(command.v_mps) +
                                ", w_radps=" + std::to_string(command.w_radps) + ") is not finite");
  }
}

}  // namespace dream::world::world_argument_check
