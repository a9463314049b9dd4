#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dream/workflows/command_runner.h"
#include "dream/workflows/slurm_task_state.h"
#include "dream/workflows/sweep_folder.h"

namespace dream::workflows {

/// The Slurm jobs of one sweep, as slurm/jobs.txt records them ("array JOBID
/// OFFSET": task T runs run OFFSET + T; "table JOBID": the job that writes
/// the table), and what Slurm knows of their tasks now.
class SlurmJobs {
 public:
  static constexpr const char* kJobsFile = "slurm/jobs.txt";

  struct ArrayJob {
    std::string job_id;
    size_t offset = 0;
  };

  /// Reads the folder's jobs.txt (none yet: no jobs). @throws
  /// std::runtime_error naming the file and line when it is damaged.
  explicit SlurmJobs(const SweepFolder& folder);

  const std::vector<ArrayJob>& arrays() const { return arrays_; }
  const std::vector<std::string>& table_jobs() const { return table_jobs_; }

  /// Appends a job to jobs.txt (atomically: the file is written anew).
  void RecordArray(const ArrayJob& job);
  void RecordTableJob(const std::string& job_id);

  /// What Slurm says of each run (by plan number) that it knows of: the
  /// tasks' logs first (slurmstepd writes cancellations and time limits
  /// there), then sacct where the cluster keeps accounting, then squeue
  /// (pending and running tasks), each later source winning; a run of a
  /// later array wins over an earlier one. `commands` may be null (logs
  /// only). `queue_note` (if given) says when squeue could not be asked.
  std::map<size_t, SlurmTaskState> TaskStates(CommandRunner* commands, std::string* queue_note) const;

  /// The job id sbatch --parsable printed ("123" or "123;cluster"), or nullopt.
  static std::optional<std::string> ParseJobId(const std::string& sbatch_output);

 private:
  void Write() const;
  /// squeue's or sacct's "JOBID_TASK|STATE" lines into `states`.
  void ApplyListing(const std::string& listing, std::map<size_t, SlurmTaskState>& states) const;

  SweepFolder folder_;
  std::vector<ArrayJob> arrays_;
  std::vector<std::string> table_jobs_;
};

}  // namespace dream::workflows
