#include "dream/hrvo_circle/formation_sequence_metrics.h"

#include <string>

namespace dream::hrvo_circle {

FormationSequenceMetrics::FormationSequenceMetrics(std::vector<std::vector<Eigen::Vector2d>> formations_m,
                                                   double tolerance_m)
    : formations_m_(std::move(formations_m)), tolerance_m_(tolerance_m) {}

void FormationSequenceMetrics::Observe(const agents::WorldSnapshot& world) {
  const size_t next = completed_steps_.size();
  if (next >= formations_m_.size()) return;
  const std::vector<Eigen::Vector2d>& points = formations_m_[next];
  if (world.poses.size() < points.size()) return;
  for (size_t i = 0; i < points.size(); ++i) {
    if ((world.poses[i].head<2>() - points[i]).norm() > tolerance_m_) return;
  }
  completed_steps_.push_back(world.step);
}

void FormationSequenceMetrics::Write(agents::MetricsReport* report) const {
  report->values["formations_completed"] = static_cast<double>(completed_steps_.size());
  for (size_t k = 0; k < formations_m_.size(); ++k) {
    report->values["formation_" + std::to_string(k + 1) + "_completed_step"] =
        k < completed_steps_.size() ? static_cast<double>(completed_steps_[k]) : -1.0;
  }
  report->values["all_formations_completed_step"] =
      completed_steps_.size() == formations_m_.size() && !completed_steps_.empty()
          ? static_cast<double>(completed_steps_.back())
          : -1.0;
  report->steps["formation_completed_steps"] = completed_steps_;
}

// Goal: every formation completed (all_formations_completed_step).
std::optional<agents::GoalJudgement> FormationSequenceMetrics::JudgeGoal(const agents::MetricsReport& report) const {
  int formations = 0;
  for (const auto& [name, value] : report.values) {
    (void)value;
    const std::string suffix = "_completed_step";
    if (name.rfind("formation_", 0) == 0 && name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      ++formations;
    }
  }
  agents::GoalJudgement goal;
  goal.completion_step = static_cast<int64_t>(report.Value("all_formations_completed_step"));
  goal.met = goal.completion_step >= 0;
  goal.detail = std::to_string(static_cast<int>(report.Value("formations_completed", 0.0))) + " of " +
                std::to_string(formations) + " formations";
  return goal;
}

}  // namespace dream::hrvo_circle
