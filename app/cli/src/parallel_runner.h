#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace dream::cli {

/// Runs numbered jobs as child processes, at most `max_parallel` at a time
/// (dream sweep: one `dream run` per job). A job still going after
/// `timeout_s` gets SIGINT, like Ctrl-C, so it can still write its outputs;
/// one still going `grace_s` after a SIGINT gets SIGKILL.
class ParallelRunner {
 public:
  struct Job {
    std::vector<std::string> argv;  ///< argv[0] is searched on PATH
    std::string output_path;        ///< stdout and stderr go here
  };
  struct Finished {
    size_t index = 0;
    int exit_code = -1;        ///< 128 + signal when killed; -1 when it could not start
    bool timed_out = false;    ///< stopped at timeout_s
    double wall_time_s = 0.0;  ///< start to exit
    std::string start_error;   ///< why it could not start (exit_code -1)
  };
  /// Prepares job `index` (may write files) and says what to start.
  /// Throwing counts as a job that could not start.
  using PrepareFn = std::function<Job(size_t index)>;
  /// Called in this thread as each job ends, in the order they end.
  using FinishedFn = std::function<void(const Finished&)>;

  ParallelRunner(int max_parallel, double timeout_s, double grace_s);

  /// Runs jobs 0..count-1 in order until all ended, or until `stop` is set:
  /// then the running ones get SIGINT, no new one starts, and Run returns
  /// once they ended. Returns false when stopped.
  bool Run(size_t count, const std::atomic<bool>& stop, const PrepareFn& prepare, const FinishedFn& finished);

 private:
  int max_parallel_;
  double timeout_s_;
  double grace_s_;
};

}  // namespace dream::cli
