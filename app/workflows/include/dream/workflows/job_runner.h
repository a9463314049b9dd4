#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace dream::workflows {

/// Runs numbered jobs (one `dream run` each), some at a time: the local
/// engine's processes. An interface so the sweep's workflow is tested without
/// starting processes; the command line's ParallelRunner starts them.
class JobRunner {
 public:
  struct Job {
    std::vector<std::string> argv;  ///< argv[0] is searched on PATH
    std::string output_path;        ///< stdout and stderr go here
  };
  struct Finished {
    size_t index = 0;
    int exit_code = -1;        ///< 128 + signal when killed; -1 when it could not start
    bool timed_out = false;    ///< stopped at the time limit
    double wall_time_s = 0.0;  ///< start to exit
    std::string start_error;   ///< why it could not start (exit_code -1)
  };
  /// Prepares job `index` (may write files) and says what to start.
  /// Throwing counts as a job that could not start.
  using PrepareFn = std::function<Job(size_t index)>;
  /// Called in the caller's thread as each job ends, in the order they end.
  using FinishedFn = std::function<void(const Finished&)>;

  virtual ~JobRunner() = default;

  /// Runs jobs 0..count-1 in order until all ended, or until `stop` is set
  /// (then no new one starts, the running ones are asked to stop, and Run
  /// returns once they ended). Returns false when stopped.
  virtual bool Run(size_t count, const std::atomic<bool>& stop, const PrepareFn& prepare,
                   const FinishedFn& finished) = 0;
};

}  // namespace dream::workflows
