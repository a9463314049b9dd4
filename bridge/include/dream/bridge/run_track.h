#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/violation_counts.h"

namespace dream::bridge {

/// Every robot's pose at every step of a run, simulated or from the lab, in
/// the form the bridge works with: steps 0..last_step() with no gap.
struct RunTrack {
  int num_robots = 0;
  /// Per step: the time it was published at, microseconds since step 0.
  std::vector<int64_t> utime;
  /// (last_step() + 1) x num_robots, step-major.
  std::vector<sim::Pose2> poses;
  /// Same size: commands[k] is what each robot drove with from step k to
  /// k + 1 (for a simulated run the saturated velocity, for a lab run the
  /// command the script sent); the last step's row is zero.
  std::vector<sim::UnicycleCommand> commands;
  /// Per step: the virtual obstacles.
  std::vector<std::vector<sim::ObstacleState>> obstacles;

  /// The last step with poses (steps taken); -1 when empty.
  int64_t last_step() const { return static_cast<int64_t>(utime.size()) - 1; }
  const sim::Pose2& pose(int64_t step, int robot) const {
    return poses[static_cast<size_t>(step) * static_cast<size_t>(num_robots) + static_cast<size_t>(robot)];
  }
  const sim::UnicycleCommand& command(int64_t step, int robot) const {
    return commands[static_cast<size_t>(step) * static_cast<size_t>(num_robots) + static_cast<size_t>(robot)];
  }
};

/// How a recorded run ended, from its last DREAM_STATUS.
struct RunEnd {
  bool seen = false;      ///< the log has a DREAM_STATUS at all
  int8_t state = -1;      ///< run_status_t state
  std::string detail;
  sim::ViolationCounts violations{};
  int64_t step = -1;
  /// Robots lost at the end: their agent fell silent or their controller failed.
  std::vector<int> lost_robot_ids;
  /// Of those, the ones whose agent said why on DREAM_FAULT_<id>: id -> "step k: detail".
  std::map<int, std::string> robot_faults;
};

/// Reads DREAM_POSES (the poses, and the velocities of the step that led to
/// them), DREAM_OBSTACLES and DREAM_STATUS from a run log: what `dream run`
/// writes and what `dream import` writes.
/// @throws std::runtime_error naming the file and the step when the log has
///         no poses, a gap or repeat in the steps, a changing robot count,
///         an undecodable world message, or is not an LCM log.
RunTrack ReadRunTrack(const std::string& log_path, RunEnd* end = nullptr);

}  // namespace dream::bridge
