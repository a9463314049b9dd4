#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dream/workflows/command_runner.h"
#include "dream/workflows/sweep_folder.h"

namespace dream::workflows {

/// Submits runs of a sweep to Slurm: one job array whose task T runs run T
/// of the plan (`sh run.sh T`, so a task runs exactly what the local engine
/// runs), at most `max_parallel` at once (`--array=0-N%K`), and a job
/// depending on it (`afterany`) that runs `dream sweep table` to write
/// sweep.csv and sweep.md. A cluster whose MaxArraySize is smaller than the
/// plan gets several arrays, each with an offset. The folder must be on a
/// file system the nodes share, and `dream_path` installed on every node.
class SlurmSubmission {
 public:
  struct Options {
    int max_parallel = 0;                     ///< %K; 0: no limit
    long long time_limit_minutes = 0;         ///< each task's --time, unless `sbatch_options` hold one
    std::vector<std::string> sbatch_options;  ///< --slurm-option values, passed on as they are
    std::string dream_path;                   ///< the dream binary the nodes run
    std::string job_name = "dream-sweep";
  };
  struct Submitted {
    std::vector<std::string> array_jobs;
    std::string table_job;
  };

  SlurmSubmission(const SweepFolder& folder, CommandRunner& commands);

  /// Writes the job scripts, submits `indices` (plan numbers, ascending) and
  /// the table job, and records them in slurm/jobs.txt.
  /// @throws std::runtime_error quoting sbatch when it refuses a job (the
  ///         arrays already submitted are recorded and named).
  Submitted Submit(const std::vector<size_t>& indices, const Options& options);

  /// "0-39%4", "3,7-9,12": `indices` minus `offset` as Slurm's --array takes
  /// them (ranges merged), with "%K" when max_parallel > 0.
  static std::string ArraySpec(const std::vector<size_t>& indices, size_t offset, int max_parallel);
  /// A task's default wall-clock limit for a run of `steps` steps, in
  /// minutes: 10 minutes plus 0.1 s per step (a 128-robot Python run needs
  /// far less), so a run that hangs does not hold a node for days.
  static long long DefaultTimeLimitMinutes(long long steps);
  /// True when one of `options` sets the time limit (--time, -t).
  static bool SetsTimeLimit(const std::vector<std::string>& options);
  /// `path` as sbatch's --output takes it: every '%' doubled, so a folder
  /// named "100%" is not read as a replacement symbol (%A, %j, ...).
  static std::string OutputPattern(const std::string& path);
  /// @throws std::invalid_argument naming `dir` when Slurm cannot name a log
  ///         in it: a backslash turns off sbatch's replacement symbols and is
  ///         itself dropped from the path.
  static void CheckFolderPath(const std::string& dir);

 private:
  /// The cluster's MaxArraySize (scontrol show config), 1001 when unknown.
  size_t MaxArraySize();
  std::string SubmitJob(std::vector<std::string> argv, const std::string& what);

  SweepFolder folder_;
  CommandRunner& commands_;
};

}  // namespace dream::workflows
