#pragma once

#include <chrono>
#include <cstdint>

namespace dream::node {

/// SimNode's state of one robot: who drives it and the command it holds.
struct RobotSlot {
  int64_t owner_agent_id = 0;
  bool owned = false;
  bool lost = false;
  bool done = false;
  double v_mps = 0.0;
  double w_radps = 0.0;
  int64_t command_step = -1;  // step of the command held in v/w/done (sent by owner_agent_id); -1: none
  int32_t conflicts = 0;      // refused different commands for command_step
  double received_v = 0.0;    // the held command as sent (v/w are zeroed when it was absurd)
  double received_w = 0.0;
  std::chrono::steady_clock::time_point last_heard;
  int64_t busy_step = -1;  // the step its agent host last said its answer is held up at (DREAM_BUSY_<id>); -1: none
  std::chrono::steady_clock::time_point busy_heard;  // when that was last said
};

}  // namespace dream::node
