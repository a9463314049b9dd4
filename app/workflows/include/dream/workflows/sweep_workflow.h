#pragma once

#include <atomic>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "dream/run_config/run_config.h"
#include "dream/workflows/command_runner.h"
#include "dream/workflows/job_runner.h"
#include "dream/workflows/slurm_submission.h"
#include "dream/workflows/sweep_outcome.h"
#include "dream/workflows/sweep_settings.h"
#include "dream/workflows/sweep_status_report.h"

namespace dream::workflows {

class SweepFolder;
class SweepPlan;
class PreparedSweep;
struct CollectedSweep;

/// `dream sweep`: one experiment over many seeds and --set values, each run
/// its own `dream run`, on this machine's cores, a Slurm job array, or
/// planned for another scheduler; then one table of outcomes, per run and
/// per value (docs/sweeps.md). Also `status`, `resume` and `table` of a
/// sweep folder. Processes and Slurm's commands come through the
/// Environment, so the whole workflow is tested without starting any.
class SweepWorkflow {
 public:
  struct Environment {
    /// The local engine's runner for `jobs` runs at once and a per-run time limit.
    std::function<std::unique_ptr<JobRunner>(int jobs, double run_timeout_s)> make_job_runner;
    CommandRunner* commands = nullptr;        ///< sbatch, squeue, sacct, scontrol (Slurm only)
    const std::atomic<bool>* stop = nullptr;  ///< set on Ctrl-C (local engine)
    std::ostream* out = nullptr;              ///< progress lines and the summary block; null: none
    bool progress = true;                     ///< a line per finished run
    std::string dream_path;                   ///< the dream binary runs start (and Slurm nodes run)
    int cores = 0;                            ///< 0: this machine's
    std::string python_runtime_dir;           ///< SweepSettings::python_runtime_dir, for resume
  };

  /// What `dream sweep resume` may change; empty/0 keeps the sweep's own.
  struct ResumeSettings {
    std::string engine;  ///< "local" or "slurm"; empty: the sweep's (plan: local)
    int jobs = 0;
    double run_timeout_s = 0.0;
    std::vector<std::string> slurm_options;
  };

  explicit SweepWorkflow(Environment environment);

  /// Checks everything, writes the sweep folder and runs, submits or plans
  /// the runs. `base`: the base config as `dream run` loads it (its own
  /// mistakes already reported with their lines). @throws on bad input
  /// before anything is written (config::ConfigError, std::invalid_argument),
  /// std::runtime_error when the folder cannot be written or sbatch refuses.
  SweepOutcome Start(const SweepSettings& settings, const run_config::RunConfig& base);

  /// Runs again every run of the sweep in `dir` without a complete result
  /// (failed, cancelled, timed out, interrupted, never started).
  /// @throws std::runtime_error when `dir` is no sweep folder, or runs of it
  ///         are still queued in Slurm.
  SweepOutcome Resume(const std::string& dir, const ResumeSettings& settings);

  /// Writes sweep.csv and sweep.md from whatever has finished, and prints
  /// the summary block. @throws std::runtime_error for no sweep folder.
  SweepOutcome Table(const std::string& dir);

  /// Counts of finished, running, pending, failed and never started runs.
  /// Table and Status take the folder's lock when no one holds it (a local
  /// sweep that does is still working), and keep it until this process
  /// exits, as every command holding an output folder does.
  SweepStatusReport Status(const std::string& dir);

  /// The sweep folder Start writes: --out as given, else sweeps/<name>, or
  /// sweeps/<name>_2, _3, ... when that holds an earlier sweep.
  static std::string ChooseFolder(const std::string& out_dir, const std::string& base_name);

 private:
  /// Every run of the folder's plan, judged from its files (and Slurm).
  CollectedSweep Collect(const SweepFolder& folder, bool check_busy) const;
  /// Runs `indices` here, `jobs` at a time; `write_run` fills a run's folder
  /// first. Returns false when stopped; `table` gets each ended run.
  bool RunLocally(const SweepFolder& folder, const SweepPlan& plan, const std::vector<size_t>& indices, int jobs,
                  double run_timeout_s, const std::function<void(size_t)>& write_run, SweepTable& table);
  /// Start's local engine: every run here, then the table.
  SweepOutcome RunAll(const SweepFolder& folder, const PreparedSweep& prepared, const SweepSettings& settings, int jobs,
                      const std::string& command, const std::string& base_name);
  /// Submits `indices` to Slurm (SlurmSubmission) and says so.
  SweepOutcome Submit(const SweepFolder& folder, const std::vector<size_t>& indices,
                      const SlurmSubmission::Options& options);
  /// Writes sweep.csv and sweep.md and prints the summary block.
  void WriteTable(const SweepFolder& folder, const SweepTable& table, const std::string& title,
                  const std::vector<std::pair<std::string, std::string>>& facts) const;
  int cores() const;

  Environment env_;
};

}  // namespace dream::workflows
