#pragma once

#include <cstdint>

#include "dream/agents/framework/experiment_metrics.h"

namespace dream::calibration_drive {

/// The calibration drive's outcome: whether its program ran to its end
/// clean, as the Robotarium's debug() judges poses: no robot centre outside
/// the arena, no two robots colliding (centres moved 0.025 m ahead along
/// their headings at most 0.135 m apart; RobotariumConstants). Writes
/// calibration_last_step, calibration_program_steps, boundary_error_steps,
/// collision_steps and the first step of each (-1: none).
class CalibrationDriveMetrics final : public agents::ExperimentMetrics {
 public:
  void Observe(const agents::WorldSnapshot& world) override;
  void Write(agents::MetricsReport* report) const override;
  /// Met: the program reached its last step with no boundary or collision
  /// error; completion_step is that step.
  std::optional<agents::GoalJudgement> JudgeGoal(const agents::MetricsReport& report) const override;

 private:
  int64_t last_step_ = -1;
  int64_t boundary_error_steps_ = 0;
  int64_t first_boundary_error_step_ = -1;
  int64_t collision_steps_ = 0;
  int64_t first_collision_step_ = -1;
};

}  // namespace dream::calibration_drive
