#pragma once

#include <cstdint>

#include "dream/agents/framework/robot.h"

namespace dream::calibration_drive {

/// Kind `calibration_drive`: drives CalibrationDrive's program open loop,
/// the command of each world step whatever the robot senses (calibrate fits
/// the response to exactly these commands), and reports done from the
/// program's last step on, so a run with stop_when_done ends with it.
class CalibrationDriveRobot final : public agents::Robot {
 public:
  CalibrationDriveRobot(int id, const agents::RobotParams& params) : agents::Robot(id, params) {}
  agents::UnicycleCommand Update(int64_t step) override;
  bool done() const override { return done_; }

 private:
  bool done_ = false;
};

}  // namespace dream::calibration_drive
