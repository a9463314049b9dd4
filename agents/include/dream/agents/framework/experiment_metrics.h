#pragma once

#include <optional>

#include "dream/agents/framework/goal_judgement.h"
#include "dream/agents/framework/metrics_report.h"
#include "dream/agents/framework/world_snapshot.h"

namespace dream::agents {

/// Computes an experiment's outcome from what the world published, step by
/// step: the same code judges a simulated run and a run imported from the
/// lab. Fed from a run's log after the run.
class ExperimentMetrics {
 public:
  virtual ~ExperimentMetrics() = default;
  /// Called for every step in order.
  virtual void Observe(const WorldSnapshot& world) = 0;
  /// Adds this experiment's figures to `report`.
  virtual void Write(MetricsReport* report) const = 0;
  /// The experiment's success rule over the figures written to `report`
  /// (all metrics' figures, after every Write): nothing (the default) for
  /// metrics that judge no goal, such as SafetyMetrics.
  virtual std::optional<GoalJudgement> JudgeGoal(const MetricsReport& report) const {
    (void)report;
    return std::nullopt;
  }
};

}  // namespace dream::agents
