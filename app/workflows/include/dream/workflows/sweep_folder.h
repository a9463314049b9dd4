#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dream/node/run_summary.h"
#include "dream/workflows/run_exit.h"
#include "dream/workflows/slurm_task_state.h"
#include "dream/workflows/sweep_plan.h"
#include "dream/workflows/sweep_run_result.h"

namespace dream::workflows {

/// A sweep's folder, the one place that knows its layout, so that every
/// engine and `dream sweep status | resume | table` read it alike
/// (docs/sweeps.md):
///
///     plan.tsv      one line per run: number, run folder, seed, the --set values
///     sweep.json    how the sweep was started (command, engine, jobs, the dream binary)
///     run.sh        `sh run.sh N` runs run N of the plan (Slurm tasks, commands.txt)
///     commands.txt  (--engine plan) one shell command per run
///     runs/<run>/   config.yaml, what dream run writes, output.txt, exit.txt (RunExit)
///     slurm/        the job scripts, jobs.txt (the jobs submitted), the tasks' logs
class SweepFolder {
 public:
  static constexpr const char* kPlanFile = "plan.tsv";
  static constexpr const char* kSettingsFile = "sweep.json";
  static constexpr const char* kRunScript = "run.sh";
  static constexpr const char* kCommandsFile = "commands.txt";
  static constexpr const char* kSlurmFolder = "slurm";
  /// Why a run whose folder is locked has no result yet.
  static constexpr const char* kRunningReason = "running (its dream run holds the run folder's lock)";
  /// The files of a run's outputs, removed before it runs (again), so an
  /// earlier attempt's cannot pass for the new one's.
  static const std::vector<std::string>& RunOutputFiles();

  /// `dir` made absolute: run.sh and the Slurm jobs run elsewhere.
  explicit SweepFolder(const std::string& dir);

  /// A run folder's name as SweepPlan makes them (letters, digits, `._-`):
  /// nothing that could leave runs/ or mean something to a shell.
  static bool IsRunName(const std::string& name);
  /// @throws std::invalid_argument naming `dir` when its absolute path holds
  ///         a control character (a newline would split commands.txt's lines
  ///         and every line-based scheduler's).
  static void CheckFolderPath(const std::string& dir);

  const std::string& dir() const { return dir_; }
  std::string Path(const std::string& relative) const { return dir_ + "/" + relative; }
  /// runs/<run_name>. @throws std::invalid_argument when `run_name` is no
  ///         run folder name (IsRunName), so no path made here leaves runs/.
  std::string RunDir(const std::string& run_name) const;
  /// Why the run's folder must not be written or read as this sweep's
  /// (runs/ or runs/<run> a symbolic link, or not a folder); empty when it
  /// is a plain folder or missing.
  std::string RunFolderProblem(const std::string& run_name) const;
  /// True when a process holds the run folder's lock: its dream run (or the
  /// run.sh around it) still works there.
  bool RunIsLocked(const std::string& run_name) const;

  /// plan.tsv: a comment, a header (index, run, seed, the keys), one line per
  /// run; tabs, newlines and backslashes in values escaped.
  void WritePlan(const SweepPlan& plan) const;
  /// @throws std::runtime_error naming plan.tsv and the line when it is not
  ///         one this class wrote (bounded: at most kMaxSweepRuns runs).
  SweepPlan ReadPlan() const;

  void WriteSettings(const nlohmann::json& settings) const;
  /// @throws std::runtime_error naming sweep.json when it is missing or damaged.
  nlohmann::json ReadSettings() const;

  /// run.sh, which runs `dream_path run` for one run of the plan and writes
  /// its exit record last, holding the run folder's lock throughout; it
  /// refuses a plan.tsv other than the one written now (its SHA-256 is in
  /// the script), a run name that is no IsRunName, a run folder that is a
  /// symbolic link, and a run another process holds.
  void WriteRunScript(const std::string& dream_path) const;
  /// "/bin/sh '<dir>/run.sh' 17": the shell command that runs run 17.
  std::string RunCommand(size_t index) const;
  /// commands.txt: RunCommand of each of `indices`, one a line.
  void WriteCommands(const std::vector<size_t>& indices) const;

  /// Removes the run's outputs and exit record (RunOutputFiles), holding
  /// the run folder's lock meanwhile. @throws std::runtime_error naming the
  /// run, and removing nothing, when its folder is a link (RunFolderProblem)
  /// or another process holds it (a run still running).
  void ClearRun(const std::string& run_name) const;
  void WriteRunExit(const std::string& run_name, const RunExit& exit) const;
  /// nullopt when the run has no record, or one that does not parse.
  /// @throws std::runtime_error naming exit.txt when it is there but cannot
  ///         be read (a FIFO, a folder: never waited on).
  std::optional<RunExit> ReadRunExit(const std::string& run_name) const;

  /// The run's row from its exit record, summary.json and (when it failed)
  /// the last error line of output.txt: the one judgement of every engine.
  SweepRunResult JudgeRun(const SweepPlan::Run& run, const RunExit& exit) const;
  /// The run's row, from what its folder holds: not run while `run_locked`
  /// (its dream run holds the folder: running) unless `slurm` says its task
  /// ended (its processes are ending: Slurm's word stands); judged from its exit record
  /// and summary.json when it has a record; else not run (`slurm` pending or
  /// running, never started, or `folder_busy`: a local sweep is working in
  /// the folder), or failed when Slurm ended it (cancelled, timed out), its
  /// folder was left half written by a killed task, its folder is a link or
  /// its exit record cannot be read.
  SweepRunResult CollectRun(const SweepPlan::Run& run, const std::optional<SlurmTaskState>& slurm, bool folder_busy,
                            bool run_locked = false) const;

  /// The last line of a run's output that says what went wrong, for the table.
  static std::string LastErrorLine(const std::string& output_path);
  /// summary.json read by node::RunSummary, or none when it is missing,
  /// larger than RunSummary::kMaxBytes, not a regular file, not JSON or a
  /// field is not what summary.json's field list says (`*problem` then says
  /// which, with the file; empty for a file that is not there).
  static std::optional<node::RunSummary> ReadSummary(const std::string& path, std::string* problem);

 private:
  std::string dir_;
};

}  // namespace dream::workflows
