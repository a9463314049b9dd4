#include "dream/agent_host/log_metrics.h"

#include "dream/agent_host/snapshot_from_messages.h"

namespace dream::agent_host {

agents::MetricsReport MetricsFromLog(const ControllerFactory& factory, const run_log::RunLog& log,
                                     std::optional<agents::GoalJudgement>* goal) {
  std::vector<std::unique_ptr<agents::ExperimentMetrics>> metrics = factory.MakeMetrics();
  agents::WorldSnapshot world;
  const obstacles_t* obstacles = nullptr;  // those in `world`
  for (size_t i = 0; i < log.poses().size(); ++i) {
    if (&log.obstacles_at(i) != obstacles) {
      obstacles = &log.obstacles_at(i);
      TakeObstacles(*obstacles, &world);
    }
    TakePoses(log.poses()[i], &world);
    for (auto& m : metrics) m->Observe(world);
  }
  agents::MetricsReport report;
  for (const auto& m : metrics) m->Write(&report);
  if (goal != nullptr) {
    goal->reset();
    for (const auto& m : metrics) {
      if (!*goal) *goal = m->JudgeGoal(report);
    }
  }
  return report;
}

}  // namespace dream::agent_host
