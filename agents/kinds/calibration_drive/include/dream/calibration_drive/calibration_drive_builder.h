#pragma once

#include <vector>

#include "dream/kind_api/experiment_builder.h"
#include "dream/config/config_node.h"

namespace dream::calibration_drive {

/// `kind: calibration_drive`: every robot drives CalibrationDrive's open-loop
/// program (config/calibration.yaml; `dream export --calibration`), and the
/// goal is that it ran to its end clean (CalibrationDriveMetrics). No keys of
/// its own: the program is fixed, so every lab run of it fits alike.
class CalibrationDriveBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "calibration_drive";
  static std::vector<const char*> Keys() { return {}; }

  CalibrationDriveBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
};

}  // namespace dream::calibration_drive
