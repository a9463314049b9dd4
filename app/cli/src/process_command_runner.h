#pragma once

#include "dream/workflows/command_runner.h"

namespace dream::cli {

/// Runs Slurm's client commands for dream sweep as child processes, their
/// output through a temporary file (at most 4 MiB of it read back), each
/// stopped after `timeout_s` (a hung slurmctld must not hang the sweep).
class ProcessCommandRunner : public workflows::CommandRunner {
 public:
  explicit ProcessCommandRunner(double timeout_s = 120.0) : timeout_s_(timeout_s) {}
  Result Run(const std::vector<std::string>& argv) override;

 private:
  double timeout_s_;
};

}  // namespace dream::cli
