#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dream/session/experiment_goal.h"
#include "dream/world/run_verdict.h"
#include "dream/world/violation_counts.h"
#include "sweep_plan.h"

namespace dream::cli {

/// What one run of a sweep gave: how its `dream run` process ended and, when
/// it wrote one, the figures of its summary.json.
///
/// A run is a **success** when it ran to its end (`end` finished: every
/// robot done or the step limit), the Robotarium would accept it (verdict not
/// rejected: no boundary, collision or obstacle errors), it has no
/// collisions, and its experiment's own goal is met (ExperimentGoal).
struct SweepRunResult {
  enum class Status {
    kRan,          ///< the process exited 0 or 3 with a finished summary
    kFailed,       ///< crashed, timed out, exited 4, or left no readable summary
    kInterrupted,  ///< stopped by Ctrl-C (exit 130)
  };

  SweepPlan::Run run;
  Status status = Status::kFailed;
  std::string problem;       ///< why it did not run (status != kRan)
  int exit_code = -1;        ///< of `dream run`; 128 + signal when killed; -1 if it did not start
  double wall_time_s = 0.0;  ///< measured by the sweep: start of the process to its exit

  bool has_summary = false;
  std::string end;      ///< summary "end"
  std::optional<world::RunVerdict> verdict;  ///< summary "verdict" (none when missing or unknown)
  long long steps = 0;
  world::ViolationCounts violations;  ///< summary "violations"
  std::optional<double> min_distance_m;  ///< metrics.min_pairwise_distance_m (robot centres)
  session::ExperimentGoal goal;
  bool success = false;

  /// Fills the fields above from the process's exit code and its summary.json
  /// (null when there is none or it could not be read), and judges success.
  /// `timed_out`: the sweep stopped it at its time limit (it failed to run).
  /// `failure_hint`: a line from the run's output to quote when it failed.
  static SweepRunResult Judge(const SweepPlan::Run& run, int exit_code, bool timed_out, double wall_time_s,
                              const nlohmann::json& summary, const std::string& failure_hint);

  /// For progress lines and the table: "success", "no success (3 collision
  /// errors; 2 of 3 formations)", "failed to run (exit 4: ...)".
  std::string OutcomeText() const;
  /// The short form for the table's outcome column (the other columns say
  /// why): "success", "no success", "failed to run (...)", "interrupted".
  std::string ShortOutcomeText() const;
  /// Collision errors plus robot-obstacle collisions.
  long long collisions() const { return violations.collision_errors + violations.obstacle_collisions; }
};

}  // namespace dream::cli
