#include "dream/calibration_drive/calibration_drive_builder.h"

#include "dream/calibration_drive/calibration_drive_metrics.h"
#include "dream/calibration_drive/calibration_drive_robot.h"

namespace dream::calibration_drive {

// The program has no parameters: each robot drives it from wherever the
// config starts it (CalibrationDrive::StartPoses lays out up to 20).
CalibrationDriveBuilder::CalibrationDriveBuilder(const config::ConfigNode& section, int num_robots) {
  (void)section;
  (void)num_robots;
}

std::unique_ptr<agents::Robot> CalibrationDriveBuilder::MakeRobot(int robot_id,
                                                                  const agents::RobotParams& params) const {
  return std::make_unique<CalibrationDriveRobot>(robot_id, params);
}

std::unique_ptr<agents::ExperimentMetrics> CalibrationDriveBuilder::MakeMetrics() const {
  return std::make_unique<CalibrationDriveMetrics>();
}

}  // namespace dream::calibration_drive
