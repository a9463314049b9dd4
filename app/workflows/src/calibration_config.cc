#include "dream/workflows/calibration_config.h"

#include <Eigen/Core>
#include <stdexcept>
#include <vector>

#include "dream/calibration_drive/calibration_drive.h"
#include "dream/world/printf_text.h"

namespace dream::workflows {

static_assert(CalibrationConfig::kMaxRobots == calibration_drive::CalibrationDrive::kMaxRobots,
              "the export offers as many robots as the program has start poses for");

std::string CalibrationConfig::Name(int robots) { return "calibration_" + std::to_string(robots); }

std::string CalibrationConfig::Text(int robots) {
  if (robots < kMinRobots || robots > kMaxRobots) {
    throw std::invalid_argument("the calibration drive runs " + std::to_string(kMinRobots) + " to " +
                                std::to_string(kMaxRobots) + " robots, not " + std::to_string(robots));
  }
  std::string text =
      "# Written by dream export --calibration: the calibration drive (config/calibration.yaml)\n"
      "# on " +
      std::to_string(robots) +
      " robots, run in the ideal simulator and exported open loop.\n"
      "name: " +
      Name(robots) +
      "\n"
      "description: " +
      std::to_string(robots) +
      " robots drive the open-loop calibration program side by side\n"
      "seed: 1\n"
      "robots: " +
      std::to_string(robots) +
      "\n"
      "steps: " +
      std::to_string(calibration_drive::CalibrationDrive::Steps()) +
      "  # the program's length\n"
      "stop_when_done: true\n"
      "world:\n"
      "  mode: lockstep\n"
      "  realism: {preset: ideal}\n"
      "initial_poses:  # calibration_drive::CalibrationDrive::StartPoses\n";
  for (const Eigen::Vector3d& pose : calibration_drive::CalibrationDrive::StartPoses(robots)) {
    text += world::PrintfText("  - [%.10g, %.10g, %.10g]\n", pose.x(), pose.y(), pose.z());
  }
  text += "controller:\n  kind: calibration_drive\n";
  return text;
}

}  // namespace dream::workflows
