#include "dream/line_deployment/line_formation_metrics.h"

#include <algorithm>
#include <cmath>

namespace dream::line_deployment {

LineFormationMetrics::LineFormationMetrics(double step_m, double converged_m, int series_every_steps)
    : step_m_(step_m), converged_m_(converged_m), series_every_steps_(std::max(1, series_every_steps)) {}

double LineFormationMetrics::StraightnessError(const agents::WorldSnapshot& world) {
  if (world.poses.empty()) return 0.0;
  double mean_y = 0.0;
  for (const Eigen::Vector3d& pose : world.poses) mean_y += pose.y();
  mean_y /= static_cast<double>(world.poses.size());
  double worst = 0.0;
  for (const Eigen::Vector3d& pose : world.poses) worst = std::max(worst, std::abs(pose.y() - mean_y));
  return worst;
}

double LineFormationMetrics::SpacingError(const agents::WorldSnapshot& world, double step_m) {
  double worst = 0.0;
  for (size_t i = 0; i + 1 < world.poses.size(); ++i) {
    worst = std::max(worst, std::abs(world.poses[i + 1].x() - world.poses[i].x() - step_m));
  }
  return worst;
}

void LineFormationMetrics::Observe(const agents::WorldSnapshot& world) {
  straightness_m_ = StraightnessError(world);
  spacing_error_m_ = SpacingError(world, step_m_);
  last_step_ = world.step;
  const bool within = straightness_m_ <= converged_m_ && spacing_error_m_ <= converged_m_;
  if (!within) {
    converged_step_ = -1;
  } else if (converged_step_ < 0) {
    converged_step_ = world.step;
  }
  if (world.step % series_every_steps_ == 0) {
    straightness_series_.emplace_back(world.step, straightness_m_);
    spacing_series_.emplace_back(world.step, spacing_error_m_);
  }
}

void LineFormationMetrics::Write(agents::MetricsReport* report) const {
  report->values["final_line_straightness_error_m"] = straightness_m_;
  report->values["final_spacing_error_m"] = spacing_error_m_;
  report->values["converged_step"] = static_cast<double>(converged_step_);
  report->values["converged_threshold_m"] = converged_m_;
  auto straightness = straightness_series_;
  auto spacing = spacing_series_;
  // Always end the series on the last step, so the final value is plotted.
  if (last_step_ >= 0 && (straightness.empty() || straightness.back().first != last_step_)) {
    straightness.emplace_back(last_step_, straightness_m_);
    spacing.emplace_back(last_step_, spacing_error_m_);
  }
  report->series["line_straightness_error_m"] = std::move(straightness);
  report->series["spacing_error_m"] = std::move(spacing);
  const agents::MetricsReport::Threshold converged{converged_m_,
                                                   "converged: within " + agents::GoalJudgement::Metres(converged_m_)};
  for (const char* name :
       {"final_line_straightness_error_m", "final_spacing_error_m", "line_straightness_error_m", "spacing_error_m"}) {
    report->thresholds[name] = converged;
  }
}

// Goal: the line converged (both errors under converged_m from then on).
std::optional<agents::GoalJudgement> LineFormationMetrics::JudgeGoal(const agents::MetricsReport& report) const {
  agents::GoalJudgement goal;
  goal.completion_step = static_cast<int64_t>(report.Value("converged_step"));
  goal.met = goal.completion_step >= 0;
  goal.detail = goal.met ? "line converged"
                         : "line not converged: straightness " +
                               agents::GoalJudgement::Metres(report.Value("final_line_straightness_error_m")) +
                               ", spacing " + agents::GoalJudgement::Metres(report.Value("final_spacing_error_m"));
  return goal;
}

}  // namespace dream::line_deployment
