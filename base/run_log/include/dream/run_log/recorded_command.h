#pragma once

#include <cstdint>

namespace dream::run_log {

/// One velocity command of a run as its log holds it (a velocity_command_t on
/// DREAM_CMD_<id>, or on DREAM_LAB_CMD_<id> for what the lab executed): the
/// step it answers, the robot it drives, who sent it and what it said.
struct RecordedCommand {
  int64_t step = 0;
  int32_t robot_id = 0;
  int64_t agent_id = 0;
  double v_mps = 0.0;
  double w_radps = 0.0;
  bool done = false;
};

}  // namespace dream::run_log
