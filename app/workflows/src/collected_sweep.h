#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dream/workflows/slurm_task_state.h"
#include "dream/workflows/sweep_plan.h"
#include "dream/workflows/sweep_run_result.h"

namespace dream::workflows {

/// Every run of a sweep folder's plan, judged from its files and Slurm
/// (SweepWorkflow::Collect), for status, resume and table.
struct CollectedSweep {
  SweepPlan plan;
  nlohmann::json settings;                           ///< sweep.json
  std::vector<SweepRunResult> results;               ///< per run, plan order
  std::vector<std::optional<SlurmTaskState>> slurm;  ///< per run: what Slurm says, if anything
  std::vector<bool> locked;                          ///< per run: its folder's lock is held (it runs)
  bool busy = false;                                 ///< a local sweep holds the folder
  std::string note;                                  ///< e.g. squeue could not be asked
  std::vector<std::string> changed_inputs;           ///< SweepInputs::Changed: what changed since planned
  std::string unchecked_inputs;                      ///< what could not be checked
};

}  // namespace dream::workflows
