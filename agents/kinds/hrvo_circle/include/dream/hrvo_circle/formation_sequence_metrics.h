#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dream/agents/framework/experiment_metrics.h"

namespace dream::hrvo_circle {

/// Judges a sequence of formations from the poses alone: formation k counts
/// as completed at the first step, after formation k-1 completed, where every
/// robot is within `tolerance_m` of its point of formation k.
///
/// Writes formations_completed, formation_<k>_completed_step (1-based k; -1
/// when not completed), all_formations_completed_step and the step list
/// formation_completed_steps.
class FormationSequenceMetrics final : public agents::ExperimentMetrics {
 public:
  /// @param formations_m formations_m[k][i] is robot i's point in formation k.
  FormationSequenceMetrics(std::vector<std::vector<Eigen::Vector2d>> formations_m, double tolerance_m);
  void Observe(const agents::WorldSnapshot& world) override;
  void Write(agents::MetricsReport* report) const override;
  std::optional<agents::GoalJudgement> JudgeGoal(const agents::MetricsReport& report) const override;

  int completed() const { return static_cast<int>(completed_steps_.size()); }
  const std::vector<int64_t>& completed_steps() const { return completed_steps_; }

 private:
  std::vector<std::vector<Eigen::Vector2d>> formations_m_;
  double tolerance_m_;
  std::vector<int64_t> completed_steps_;
};

}  // namespace dream::hrvo_circle
