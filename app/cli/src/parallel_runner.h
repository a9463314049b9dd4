#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "dream/workflows/job_runner.h"

namespace dream::cli {

/// Runs numbered jobs as child processes, at most `max_parallel` at a time
/// (dream sweep: one `dream run` per job). A job still going after
/// `timeout_s` gets SIGINT, like Ctrl-C, so it can still write its outputs;
/// one still going `grace_s` after a SIGINT gets SIGKILL.
class ParallelRunner : public workflows::JobRunner {
 public:
  using Job = workflows::JobRunner::Job;
  using Finished = workflows::JobRunner::Finished;

  ParallelRunner(int max_parallel, double timeout_s, double grace_s);

  /// Runs jobs 0..count-1 in order until all ended, or until `stop` is set:
  /// then the running ones get SIGINT, no new one starts, and Run returns
  /// once they ended. Returns false when stopped.
  bool Run(size_t count, const std::atomic<bool>& stop, const PrepareFn& prepare, const FinishedFn& finished) override;

 private:
  int max_parallel_;
  double timeout_s_;
  double grace_s_;
};

}  // namespace dream::cli
