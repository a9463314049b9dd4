#pragma once

#include <cstdint>
#include <vector>

#include "dream/agents/framework/experiment_metrics.h"

namespace dream::line_deployment {

/// Judges a line deployment from the poses alone, per step:
///   straightness error = max_i |y_i - mean y|,
///   spacing error      = max over consecutive ids |(x_{i+1} - x_i) - step|,
/// where `step_m` is the signed x step from one id to the next on the final
/// line (eq. 3.7 as the thesis prints it gives step = -d: robot 0 rightmost).
/// Writes both as series (every `series_every_steps` steps, and the last
/// step) and final values, and converged_step: the first step from which
/// both stay within `converged_m` to the end of the run (-1 if they do not
/// at the end).
class LineFormationMetrics final : public agents::ExperimentMetrics {
 public:
  LineFormationMetrics(double step_m, double converged_m, int series_every_steps = 10);
  void Observe(const agents::WorldSnapshot& world) override;
  void Write(agents::MetricsReport* report) const override;
  std::optional<agents::GoalJudgement> JudgeGoal(const agents::MetricsReport& report) const override;

  /// Errors of one set of poses, for tests and plotting.
  static double StraightnessError(const agents::WorldSnapshot& world);
  static double SpacingError(const agents::WorldSnapshot& world, double step_m);

 private:
  double step_m_;
  double converged_m_;
  int series_every_steps_;
  int64_t converged_step_ = -1;
  int64_t last_step_ = -1;
  double straightness_m_ = 0.0;
  double spacing_error_m_ = 0.0;
  std::vector<std::pair<int64_t, double>> straightness_series_;
  std::vector<std::pair<int64_t, double>> spacing_series_;
};

}  // namespace dream::line_deployment
