#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dream/agents/framework/unicycle_command.h"

namespace dream::calibration_drive {

/// The drive that shows `dream calibrate` what it fits: every robot, side by
/// side, does the same open-loop program of steps from rest in v (0.05,
/// 0.1 and 0.19 m/s, forward and back), turns in place (1 and 2 rad/s, both
/// ways), an arc there and back, each followed by a rest, and a long rest at
/// the end. Forward and back, so each robot ends near where it started; side
/// by side, so no two come closer than their spacing. The robots of kind
/// `calibration_drive` drive it (CalibrationDriveRobot); `dream export
/// --calibration` ships a run of it.
class CalibrationDrive {
 public:
  /// The command at `step` (0 before step 0 and from the program's end on).
  static agents::UnicycleCommand CommandAt(int64_t step);
  /// Steps the program lasts (about 47 s).
  static int64_t Steps();
  /// Start poses [x m, y m, theta rad] for `robots` robots (1..kMaxRobots):
  /// rows across the arena, facing +x, far enough apart and from the walls
  /// for the program.
  /// @throws std::invalid_argument for a count outside 1..kMaxRobots.
  static std::vector<Eigen::Vector3d> StartPoses(int robots);
  static constexpr int kMaxRobots = 20;
};

}  // namespace dream::calibration_drive
