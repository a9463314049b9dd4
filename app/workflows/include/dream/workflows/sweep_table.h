#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dream/workflows/sweep_run_result.h"

namespace dream::workflows {

/// The figures of a whole sweep (docs/sweeps.md). Success rate = successes /
/// runs that ran or failed to run; interrupted runs are counted apart.
struct SweepSummary {
  size_t planned = 0;
  size_t listed = 0;  ///< runs in the table (started)
  size_t ran = 0;
  size_t failed = 0;  ///< failed to run (crash, timeout, exit 4)
  size_t interrupted = 0;
  size_t not_run = 0;  ///< no result yet or never started (dream sweep table on a sweep not done)
  size_t succeeded = 0;
  size_t without_goal = 0;    ///< ran, but their experiment declares no goal: never a success
  double success_rate = 0.0;  ///< 0..1; 0 when nothing was judged
  size_t completed = 0;       ///< runs with a completion step
  double completion_mean = 0.0;
  long long completion_min = -1;
  long long completion_max = -1;
  bool has_min_distance = false;
  double worst_min_distance_m = 0.0;  ///< the smallest min_pairwise_distance_m of any run
  std::string worst_min_distance_run;
  world::ViolationCounts violations;  ///< summed over every run
};

/// One row per run, in plan order, written as CSV (for scripts) and Markdown
/// (for people): sweep.csv and sweep.md.
class SweepTable {
 public:
  SweepTable(std::vector<std::string> parameter_keys, size_t planned_runs);

  /// Adds a finished run; rows are kept in plan order whatever order runs end in.
  void Add(SweepRunResult result);
  const std::vector<SweepRunResult>& results() const { return results_; }

  SweepSummary Summary() const;
  /// Header row plus one row per run; fields quoted as RFC 4180 asks.
  std::string Csv() const;
  /// The summary block: `facts` (e.g. command, jobs, wall time) first, then
  /// the figures of Summary(), as a two-column table.
  std::string SummaryMarkdown(const std::vector<std::pair<std::string, std::string>>& facts) const;
  /// The per-value (and per-combination) figures (SweepValueStats), at most
  /// `max_rows` rows a table; empty without --set keys.
  std::string ByValueMarkdown(size_t max_rows) const;
  /// "# title", the summary block, the per-value figures and the table of runs.
  std::string Markdown(const std::string& title, const std::vector<std::pair<std::string, std::string>>& facts) const;

 private:
  std::vector<std::string> keys_;
  size_t planned_;
  std::vector<SweepRunResult> results_;
};

}  // namespace dream::workflows
