#pragma once

#include <optional>
#include <string>

namespace dream::workflows {

/// What Slurm says of one task of a sweep's job array: from squeue (pending,
/// running), sacct (how it ended, when the cluster keeps accounting), or the
/// task's log, where slurmstepd writes "*** JOB 12 ON node CANCELLED AT ...
/// [DUE TO TIME LIMIT] ***" when it ends a task.
struct SlurmTaskState {
  enum class State { kPending, kRunning, kCompleted, kCancelled, kTimedOut, kFailed };

  State state = State::kFailed;
  std::string word;  ///< Slurm's own word for it: PENDING, CANCELLED, NODE_FAIL, OUT_OF_MEMORY, ...

  bool Queued() const { return state == State::kPending || state == State::kRunning; }
  /// For the table's problem column: "cancelled in Slurm (CANCELLED)",
  /// "Slurm's time limit for the task ran out (TIMEOUT)", "pending in Slurm".
  std::string Why() const;

  /// squeue's or sacct's state name ("CANCELLED by 0" as sacct prints it);
  /// nullopt for a word that says nothing here (empty).
  static std::optional<SlurmTaskState> FromSlurmWord(const std::string& text);
  /// The state slurmstepd wrote into a task's log (its last lines), if any.
  static std::optional<SlurmTaskState> FromTaskLog(const std::string& log_tail);
};

}  // namespace dream::workflows
