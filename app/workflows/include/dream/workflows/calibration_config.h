#pragma once

#include <string>

namespace dream::workflows {

/// The run behind `dream export --calibration --robots N`: the config of N
/// robots driving the calibration program (kind calibration_drive, start
/// poses calibration_drive::CalibrationDrive::StartPoses(N), steps = the program's
/// length, the ideal world), as config/calibration.yaml is for 8.
/// It names the kind, so it lives here, above the kinds, and the bridge names none.
class CalibrationConfig {
 public:
  static constexpr int kMinRobots = 1;
  static constexpr int kMaxRobots = 20;  ///< the lab's limit, and the start poses'

  /// "calibration_N": the run's name, so runs/calibration_N and exports/calibration_N.
  static std::string Name(int robots);
  /// The config's YAML text.
  /// @throws std::invalid_argument for a count outside kMinRobots..kMaxRobots.
  static std::string Text(int robots);
};

}  // namespace dream::workflows
