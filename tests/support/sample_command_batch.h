#pragma once

#include <cstdint>
#include <vector>

#include "dream/robot_commands_t.hpp"

namespace dream::testing {

/// A DREAM_CMDS message of run `run_id` from agent `agent_id` at `step`, one
/// entry per id in order: robot k asks v = 0.01 (k + 1), w = -0.1 (k + 1),
/// and robot 1 alone says done, so every entry's fields differ.
inline robot_commands_t SampleCommandBatch(const std::vector<int32_t>& ids, int64_t run_id, int64_t agent_id,
                                           int64_t step = 0, int64_t utime = 0) {
  robot_commands_t batch{};
  batch.utime = utime;
  batch.step = step;
  batch.run_id = run_id;
  batch.agent_id = agent_id;
  batch.num_commands = static_cast<int32_t>(ids.size());
  for (const int32_t id : ids) {
    batch.robot_id.push_back(id);
    batch.v.push_back(0.01 * (id + 1));
    batch.w.push_back(-0.1 * (id + 1));
    batch.done.push_back(id == 1 ? 1 : 0);
  }
  return batch;
}

}  // namespace dream::testing
