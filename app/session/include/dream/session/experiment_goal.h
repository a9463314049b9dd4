#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dream/node/run_summary.h"
#include "dream/world/verdict_reason.h"

namespace dream::session {

/// Whether a run met its experiment's own goal, read from summary.json:
/// metrics.goal, which the kind's own success rule wrote when the run's
/// metrics were computed (agents::ExperimentMetrics::JudgeGoal; each
/// built-in kind's rule is documented in docs/experiments.md). A kind without
/// a rule (e.g. a one-class plugin) has no goal of its own: always met, its
/// completion the last step when every robot reported done. Metrics that
/// could not be computed (metrics.error) count as not met.
struct ExperimentGoal {
  std::string kind;            ///< metrics.kind ("" when missing)
  bool has_criterion = false;  ///< the kind judged its goal (metrics.goal), or its metrics failed
  bool met = false;
  long long completion_step = -1;  ///< -1: never completed
  std::string detail;              ///< short, for tables: "3 of 3 formations", "not settled"
  /// Why the goal could not be judged (metrics.error: a goal() or metrics()
  /// that raised or hung, unusable goal points); "" when it was. A run whose
  /// goal failed to be judged is not ready whatever stopped it, --steps too.
  std::string judge_error;

  /// Judges a summary.json (its metrics, robots, robots_done and steps).
  /// Missing metrics count as not met.
  static ExperimentGoal Judge(const node::RunSummary& summary);

  /// The verdict reason "goal" (not_ready) when the kind has a criterion and
  /// the run missed it; none otherwise.
  std::optional<world::VerdictReason> Reason() const;
  /// {kind, has_criterion, met, completion_step, detail} for summary.json,
  /// and judge_error when there is one.
  nlohmann::ordered_json Json() const;
  /// One line for summary.json's goal (as Json() writes it): "met at step N
  /// (detail)", "missed (detail)", "could not be judged: error", or "none declared".
  static std::string Text(const nlohmann::json& goal);
};

}  // namespace dream::session
