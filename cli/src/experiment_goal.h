#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dream/sim/verdict_reason.h"

namespace dream::cli {

/// Whether a run met its experiment's own goal, judged from summary.json's
/// "metrics" -- the one place where a sweep decides this per controller kind
/// (docs/sweeps.md shows the same list). Goal met when ... (completion step):
///
///  - go_to_goal: all_arrived_step >= 0, every robot within its tolerance at
///    once (all_arrived_step)
///  - hrvo_circle: all_formations_completed_step >= 0 (the same)
///  - line_deployment: converged_step >= 0, both line errors under
///    converged_m from then to the end (converged_step)
///  - voronoi_coverage: settled_step >= 0, every robot still for the last 30+
///    steps (settled_step); or, when robots never settle (blocks moving to the
///    last step), the coverage cost fell to at most half its initial value and
///    never rose by more than 1% of it (no completion step)
///  - affine_formation: max_follower_error_after_convergence_m <=
///    follower_error_tolerance_m (settled_step)
///  - any other kind: no goal of its own, always met (the last step, when
///    every robot reported done)
struct ExperimentGoal {
  std::string kind;            ///< metrics.kind ("" when missing)
  bool has_criterion = false;  ///< the kind is in the list above
  bool met = false;
  long long completion_step = -1;  ///< -1: never completed
  std::string detail;              ///< short, for tables: "3 of 3 formations", "not settled"

  /// Judges a parsed summary.json. Missing metrics count as not met.
  static ExperimentGoal Judge(const nlohmann::json& summary);

  /// The verdict reason "goal" (not_ready) when the kind has a criterion and
  /// the run missed it; none otherwise.
  std::optional<sim::VerdictReason> Reason() const;
  /// {kind, has_criterion, met, completion_step, detail} for summary.json.
  nlohmann::ordered_json Json() const;
};

}  // namespace dream::cli
