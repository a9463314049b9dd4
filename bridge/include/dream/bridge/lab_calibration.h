#pragma once

#include <vector>

#include "dream/bridge/calibration_report.h"
#include "dream/bridge/calibration_run.h"
#include "dream/world/realism_params.h"

namespace dream::bridge {

/// Fits world.realism's lab model to real runs (`dream calibrate`): the
/// delay, wheel lag and start-up, each robot's gains and drift by running
/// world::RobotResponse on the commands the runs sent and matching the motion
/// their poses show; the tracker's noise, rounding and repeated poses, and
/// the loop's timing, from the poses and times directly. Keys the data
/// cannot determine keep the base preset's value and say so.
class LabCalibration {
 public:
  explicit LabCalibration(world::RealismParams base = world::RealismParams::Lab()) : base_(base) {}

  /// @throws std::runtime_error when the runs hold nothing to fit (no robot
  ///         ever commanded to move, or never moving), naming why.
  CalibrationReport Fit(const std::vector<CalibrationRun>& runs) const;

 private:
  world::RealismParams base_;
};

}  // namespace dream::bridge
