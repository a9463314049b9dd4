#pragma once

#include <utility>
#include <vector>

#include "dream/calibration/calibration_report.h"
#include "dream/calibration/calibration_run.h"
#include "dream/files/stop_token.h"
#include "dream/world/realism_params.h"

namespace dream::calibration {

/// Fits world.realism's lab model to real runs (`dream calibrate`): the
/// delay, wheel lag and start-up, each robot's gains and drift by running
/// world::RobotResponse on the commands the runs sent and matching the motion
/// their poses show; the tracker's noise, rounding and repeated poses, and
/// the loop's timing, from the poses and times directly. Keys the data
/// cannot determine keep the base preset's value and say so.
class LabCalibration {
 public:
  /// `stop`: polled between the fit's stages and within its search (at
  /// least every few milliseconds of work), so Ctrl-C ends a long fit at once.
  explicit LabCalibration(world::RealismParams base = world::RealismParams::Lab(), files::StopToken stop = {})
      : base_(base), stop_(std::move(stop)) {}

  /// @throws std::runtime_error when the runs hold nothing to fit (no robot
  ///         ever commanded to move, or never moving), naming why;
  ///         files::Stopped when the stop token is requested meanwhile.
  CalibrationReport Fit(const std::vector<CalibrationRun>& runs) const;

 private:
  world::RealismParams base_;
  files::StopToken stop_;
};

}  // namespace dream::calibration
