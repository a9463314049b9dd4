#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dream/node/run_outcome.h"
#include "dream/node/run_summary.h"
#include "dream/session/experiment_goal.h"
#include "dream/world/run_verdict.h"
#include "dream/world/violation_counts.h"
#include "dream/workflows/sweep_plan.h"

namespace dream::workflows {

/// What one run of a sweep gave: how its `dream run` process ended and, when
/// it wrote one, the figures of its summary.json.
///
/// A run is a **success** when it ran to its end (`end` finished: every
/// robot done or the step limit), the Robotarium would accept it (verdict not
/// rejected: no boundary, collision or obstacle errors), it has no
/// collisions, and its experiment's own goal is met (ExperimentGoal). A run
/// whose experiment declares no goal (has_criterion false) is never a
/// success: its outcome says "no goal declared".
struct SweepRunResult {
  enum class Status {
    kRan,          ///< the process exited 0 or 3 with a finished summary
    kFailed,       ///< crashed, timed out, exited 4, or left no readable summary
    kInterrupted,  ///< stopped by Ctrl-C (exit 130)
    kNotRun,       ///< no result yet: never started, pending or running (`problem` says which)
  };

  SweepPlan::Run run;
  Status status = Status::kFailed;
  std::string problem;       ///< why it did not run (status != kRan)
  int exit_code = -1;        ///< of `dream run`; 128 + signal when killed; -1 if it did not start
  double wall_time_s = 0.0;  ///< measured by the sweep: start of the process to its exit

  bool has_summary = false;
  std::string run_id;                        ///< summary "run_id": two runs with one id are one summary copied
  std::optional<node::RunOutcome::End> end;  ///< summary "end" (none: the summary has none)
  std::optional<world::RunVerdict> verdict;  ///< summary "verdict" (none: the summary has none)
  long long steps = 0;
  world::ViolationCounts violations;     ///< summary "violations"
  std::optional<double> min_distance_m;  ///< metrics.min_pairwise_distance_m (robot centres)
  session::ExperimentGoal goal;
  bool success = false;

  /// Fills the fields above from the process's exit code and its summary.json
  /// (none when there is none or it could not be read: `summary_problem`
  /// says why, e.g. the field that is wrong), and judges success.
  /// `timed_out`: the sweep stopped it at its time limit (it failed to run).
  /// `failure_hint`: a line from the run's output to quote when it failed.
  static SweepRunResult Judge(const SweepPlan::Run& run, int exit_code, bool timed_out, double wall_time_s,
                              const std::optional<node::RunSummary>& summary, const std::string& failure_hint,
                              const std::string& summary_problem = "");

  /// For progress lines and the table: "success", "no success (3 collision
  /// errors; 2 of 3 formations)", "failed to run (exit 4: ...)".
  std::string OutcomeText() const;
  /// The short form for the table's outcome column (the other columns say
  /// why): "success", "no success", "failed to run (...)", "interrupted".
  std::string ShortOutcomeText() const;
  /// A run with no exit record yet (`dream sweep table` while it works, or
  /// a task that never started): status kNotRun, `why` in the problem column.
  static SweepRunResult NotRun(const SweepPlan::Run& run, const std::string& why);
  /// Marks the results whose summaries share a run id (one run's summary.json
  /// copied into another's folder) as failed, naming the other run.
  static void RefuseSharedRunIds(std::vector<SweepRunResult>& results);
  /// A run that left no exit record because something outside it ended it
  /// (Slurm cancelled it or hit its time limit, a killed task): failed to run.
  static SweepRunResult LostRun(const SweepPlan::Run& run, const std::string& why);

  /// Collision errors plus robot-obstacle collisions.
  long long collisions() const { return violations.collision_errors + violations.obstacle_collisions; }
};

}  // namespace dream::workflows
