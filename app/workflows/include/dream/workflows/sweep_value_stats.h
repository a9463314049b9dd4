#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dream/workflows/sweep_run_result.h"

namespace dream::workflows {

/// A sweep's figures per `--set` value and per combination of values
/// (issue 25 item 5): a grid's summary that lumps every value together says
/// nothing about which value works. Each group counts its runs as the whole
/// sweep does (SweepTable::Summary): success rate over the runs that ran or
/// failed to run, completion steps over those that completed, and the
/// closest approach of any of its runs.
class SweepValueStats {
 public:
  struct Group {
    std::string label;  ///< "controller.max_speed_mps=0.1", or "a=1, b=2" for a combination
    size_t runs = 0;    ///< every run of the group in the table
    size_t judged = 0;  ///< ran or failed to run: the success rate's denominator
    size_t succeeded = 0;
    size_t without_goal = 0;  ///< ran with no goal declared
    size_t completed = 0;     ///< runs with a completion step
    double completion_mean = 0.0;
    long long completion_min = -1;
    long long completion_max = -1;
    bool has_min_distance = false;
    double closest_m = 0.0;   ///< the smallest min_pairwise_distance_m of its runs
    std::string closest_run;  ///< the run that came that close
  };

  /// Groups `results` (rows of a table whose --set keys are `keys`).
  SweepValueStats(const std::vector<std::string>& keys, const std::vector<SweepRunResult>& results);

  /// One group per key and value, keys in --set order, values in plan order.
  const std::vector<Group>& by_value() const { return by_value_; }
  /// One group per combination of values, when there are two keys or more.
  const std::vector<Group>& by_combination() const { return by_combination_; }

  /// "## By value" (and "## By combination") as Markdown tables; empty with
  /// no --set. At most `max_rows` rows per table, then a line saying how
  /// many more (the console is bounded; sweep.md gets them all).
  std::string Markdown(size_t max_rows) const;

 private:
  std::vector<Group> by_value_;
  std::vector<Group> by_combination_;
};

}  // namespace dream::workflows
