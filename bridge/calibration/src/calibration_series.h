#pragma once

#include <string>
#include <vector>

#include "dream/calibration/calibration_run.h"
#include "dream/world/pose2.h"
#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_command.h"

namespace dream::calibration {

// One robot of one calibration run, as the fits read it.
struct CalibrationSeries {
  std::string run;
  int robot = 0;
  std::vector<world::Pose2> poses;               // per step, as measured
  std::vector<world::UnicycleCommand> commands;  // per step, as sent
  std::vector<double> step_s;                    // per step but the last: how long it lasted
  std::vector<bool> stale;                       // the pose repeats the step before's exactly
  // A step within a few steps of a late one (a loop stall): which
  // measurement shows its motion depends on the tracker's delay, so the fits
  // of motion and noise leave these out.
  std::vector<bool> near_late;
  bool timed = false;
  // Commanded to move but never moved 2 cm (a robot off or held): left out
  // of the fits of motion, as it says nothing of how robots answer commands.
  bool stuck = false;

  size_t steps() const { return poses.size(); }

  static std::vector<CalibrationSeries> Of(const std::vector<CalibrationRun>& runs);
};

// A command to stand still: what the world would not count as moving.
inline bool IsRestCommand(const world::UnicycleCommand& command) { return !world::RealisticWorld::IsMoving(command); }

// Heading difference wrapped to (-pi, pi].
double WrappedAngle(double radians);

}  // namespace dream::calibration
