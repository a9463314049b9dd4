#pragma once

#include <nlohmann/json.hpp>
#include <string>

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
///    steps (settled_step)
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
};

}  // namespace dream::cli
