#pragma once

#include <string>
#include <vector>

#include "dream/workflows/sweep_table.h"

namespace dream::workflows {

/// How a sweep command ended, for the command line's exit code.
struct SweepOutcome {
  enum class Kind {
    kFinished,     ///< the runs ran here (or the table was written): see `summary`
    kInterrupted,  ///< stopped (Ctrl-C); the table holds the runs that ended
    kSubmitted,    ///< handed to Slurm: `jobs` are the job ids
    kPlanned,      ///< --engine plan: commands.txt written, nothing run
  };
  Kind kind = Kind::kFinished;
  std::string out_dir;
  SweepSummary summary;
  std::vector<std::string> jobs;  ///< kSubmitted: the job arrays, then the table job
  size_t runs = 0;                ///< runs run, submitted or planned by this command

  /// Every planned run ran to its end (successful or not).
  bool AllRan() const {
    return kind == Kind::kFinished && summary.failed == 0 && summary.interrupted == 0 && summary.not_run == 0 &&
           summary.listed == summary.planned;
  }
};

}  // namespace dream::workflows
