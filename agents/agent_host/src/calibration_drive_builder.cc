#include "dream/agent_host/calibration_drive_builder.h"

#include "dream/agents/experiments/calibration_drive_metrics.h"
#include "dream/agents/experiments/calibration_drive_robot.h"

namespace dream::agent_host {

// The program has no parameters: each robot drives it from wherever the
// config starts it (CalibrationDrive::StartPoses lays out up to 20).
CalibrationDriveBuilder::CalibrationDriveBuilder(const config::ConfigNode& section, int num_robots) {
  (void)section;
  (void)num_robots;
}

std::unique_ptr<agents::Robot> CalibrationDriveBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  return std::make_unique<agents::CalibrationDriveRobot>(robot_id, params);
}

std::unique_ptr<agents::ExperimentMetrics> CalibrationDriveBuilder::MakeMetrics() const {
  return std::make_unique<agents::CalibrationDriveMetrics>();
}

}  // namespace dream::agent_host
