#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "dream/run_log/run_log.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/violation_counts.h"

namespace dream::bridge {

/// Every robot's pose at every step of a run, simulated or from the lab, in
/// the form the bridge works with: steps 0..last_step() with no gap. A view
/// of a whole run log (RunTrackOf), or what `dream import` builds from the
/// lab's files before it writes their log.
struct RunTrack {
  int num_robots = 0;
  /// Per step: the time it was published at, microseconds since step 0.
  std::vector<int64_t> utime;
  /// (last_step() + 1) x num_robots, step-major.
  std::vector<world::Pose2> poses;
  /// Same size: commands[k] is what each robot drove with from step k to
  /// k + 1 (for a simulated run the saturated velocity, for a lab run the
  /// command the script sent); the last step's row is zero.
  std::vector<world::UnicycleCommand> commands;
  /// Per step: the virtual obstacles.
  std::vector<std::vector<world::ObstacleState>> obstacles;

  /// The last step with poses (steps taken); -1 when empty.
  int64_t last_step() const { return static_cast<int64_t>(utime.size()) - 1; }
  const world::Pose2& pose(int64_t step, int robot) const {
    return poses[static_cast<size_t>(step) * static_cast<size_t>(num_robots) + static_cast<size_t>(robot)];
  }
  const world::UnicycleCommand& command(int64_t step, int robot) const {
    return commands[static_cast<size_t>(step) * static_cast<size_t>(num_robots) + static_cast<size_t>(robot)];
  }
};

/// How a recorded run ended, from its last DREAM_STATUS (run_log::RunLog's
/// last_status() and robot_faults()).
struct RunEnd {
  bool seen = false;  ///< the log has a DREAM_STATUS at all
  int8_t state = -1;  ///< run_status_t state
  std::string detail;
  world::ViolationCounts violations{};
  int64_t step = -1;
  /// Robots lost at the end: their agent fell silent or their controller failed.
  std::vector<int> lost_robot_ids;
  /// Of those, the ones whose agent said why on DREAM_FAULT_<id>: id -> "step k: detail".
  std::map<int, std::string> robot_faults;
};

/// The run of `log` (what `dream run` and `dream import` write): its
/// DREAM_POSES (the poses, and the velocities of the step that led to them)
/// with the obstacles of each step, and, when `end` is given, how it ended.
/// @throws std::runtime_error with the log's flaw (RunLog::Flaw, the status
///         counting when `end` is given): a message of the world that does
///         not decode, a gap or repeat in the steps, a changing robot count,
///         no poses; or naming the log, robot (or obstacle) and step when a
///         pose, velocity or obstacle is not finite.
RunTrack RunTrackOf(const run_log::RunLog& log, RunEnd* end = nullptr);

/// RunTrackOf(run_log::RunLog::Read(log_path), end), for the commands that
/// have only the log (export, lab-replay).
/// @throws std::runtime_error naming the file as RunLog::Read and RunTrackOf do.
RunTrack ReadRunTrack(const std::string& log_path, RunEnd* end = nullptr);

}  // namespace dream::bridge
