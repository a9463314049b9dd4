#include "dream/calibration_drive/calibration_drive_metrics.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dream/calibration_drive/calibration_drive.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::calibration_drive {
namespace {

using robotarium::RobotariumConstants;

bool OutsideArena(const Eigen::Vector3d& pose) {
  return pose.x() < RobotariumConstants::kArenaXMinMeters || pose.x() > RobotariumConstants::kArenaXMaxMeters ||
         pose.y() < RobotariumConstants::kArenaYMinMeters || pose.y() > RobotariumConstants::kArenaYMaxMeters;
}

}  // namespace

void CalibrationDriveMetrics::Observe(const agents::WorldSnapshot& world) {
  last_step_ = world.step;
  bool outside = false;
  std::vector<Eigen::Vector2d> fronts;
  fronts.reserve(world.poses.size());
  for (const Eigen::Vector3d& pose : world.poses) {
    outside = outside || OutsideArena(pose);
    fronts.push_back(pose.head<2>() + RobotariumConstants::kCollisionOffsetMeters *
                                          Eigen::Vector2d(std::cos(pose.z()), std::sin(pose.z())));
  }
  bool collision = false;
  // O(N^2) over at most 20 robots, after the run.
  for (size_t i = 0; i < fronts.size() && !collision; ++i) {
    for (size_t j = i + 1; j < fronts.size(); ++j) {
      if ((fronts[i] - fronts[j]).norm() <= RobotariumConstants::kCollisionDiameterMeters) {
        collision = true;
        break;
      }
    }
  }
  if (outside) {
    ++boundary_error_steps_;
    if (first_boundary_error_step_ < 0) first_boundary_error_step_ = world.step;
  }
  if (collision) {
    ++collision_steps_;
    if (first_collision_step_ < 0) first_collision_step_ = world.step;
  }
}

void CalibrationDriveMetrics::Write(agents::MetricsReport* report) const {
  report->values["calibration_program_steps"] = static_cast<double>(CalibrationDrive::Steps());
  report->values["calibration_last_step"] = static_cast<double>(last_step_);
  report->values["boundary_error_steps"] = static_cast<double>(boundary_error_steps_);
  report->values["first_boundary_error_step"] = static_cast<double>(first_boundary_error_step_);
  report->values["collision_steps"] = static_cast<double>(collision_steps_);
  report->values["first_collision_step"] = static_cast<double>(first_collision_step_);
}

std::optional<agents::GoalJudgement> CalibrationDriveMetrics::JudgeGoal(const agents::MetricsReport& report) const {
  const auto program_steps = static_cast<int64_t>(report.Value("calibration_program_steps"));
  const auto last_step = static_cast<int64_t>(report.Value("calibration_last_step"));
  const auto boundary = static_cast<int64_t>(report.Value("boundary_error_steps"));
  const auto collisions = static_cast<int64_t>(report.Value("collision_steps"));
  agents::GoalJudgement goal;
  // Missing figures read as -1: never met.
  const bool ended = program_steps > 0 && last_step >= program_steps;
  goal.met = ended && boundary == 0 && collisions == 0;
  goal.completion_step = goal.met ? program_steps : -1;
  if (goal.met) {
    goal.detail = "the program ran clean";
  } else if (boundary != 0 || collisions != 0) {
    goal.detail = std::to_string(std::max<int64_t>(boundary, 0)) + " steps outside the arena (first " +
                  std::to_string(static_cast<int64_t>(report.Value("first_boundary_error_step"))) + "), " +
                  std::to_string(std::max<int64_t>(collisions, 0)) + " with a collision (first " +
                  std::to_string(static_cast<int64_t>(report.Value("first_collision_step"))) + ")";
  } else {
    goal.detail = "cut short at step " + std::to_string(last_step) + " of " + std::to_string(program_steps);
  }
  return goal;
}

}  // namespace dream::calibration_drive
