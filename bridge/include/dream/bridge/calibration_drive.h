#pragma once

#include <cstdint>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/unicycle_command.h"

namespace dream::bridge {

/// The drive that shows `dream calibrate` what it fits: every robot, side by
/// side, does the same open-loop program of steps from rest in v (0.05,
/// 0.1 and 0.19 m/s, forward and back), turns in place (1 and 2 rad/s, both
/// ways), an arc there and back, each followed by a rest, and a long rest at
/// the end. Forward and back, so each robot ends near where it started; side
/// by side, so no two come closer than their spacing.
class CalibrationDrive {
 public:
  /// The command at `step` (0 from the program's end on).
  static sim::UnicycleCommand CommandAt(int64_t step);
  /// Steps the program lasts (about 47 s).
  static int64_t Steps();
  /// Start poses for `robots` robots (1..kMaxRobots): rows across the arena,
  /// facing +x, far enough apart and from the walls for the program.
  static std::vector<sim::Pose2> StartPoses(int robots);
  static constexpr int kMaxRobots = 20;
};

}  // namespace dream::bridge
