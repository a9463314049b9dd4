#pragma once

#include <string>
#include <vector>

namespace dream::workflows {

/// Runs one short command to its end and hands back what it printed: the
/// Slurm client commands (sbatch, squeue, sacct, scontrol). An interface so
/// the Slurm engine is tested without a cluster; the command line starts
/// real processes.
class CommandRunner {
 public:
  struct Result {
    int exit_code = -1;  ///< -1: could not start (`output` says why)
    std::string output;  ///< stdout and stderr, bounded by the runner
  };
  virtual ~CommandRunner() = default;
  /// Runs `argv` (argv[0] searched on PATH) with stdin from /dev/null.
  virtual Result Run(const std::vector<std::string>& argv) = 0;
};

}  // namespace dream::workflows
