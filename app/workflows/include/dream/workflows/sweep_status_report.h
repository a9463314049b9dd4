#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace dream::workflows {

/// `dream sweep status DIR`: how many runs of a sweep have finished, are
/// running or pending, failed, or never started, from the folder and Slurm.
struct SweepStatusReport {
  std::string out_dir;
  std::string engine;
  size_t planned = 0;
  size_t finished = 0;     ///< ran to their end (exit record and summary)
  size_t failed = 0;       ///< failed to run: crashed, cancelled, timed out, killed half way
  size_t interrupted = 0;  ///< stopped by Ctrl-C
  size_t running = 0;
  size_t pending = 0;
  size_t not_started = 0;  ///< never started (and not queued)
  size_t succeeded = 0;
  /// Why runs did not finish, and how many each: "cancelled in Slurm (CANCELLED)" -> 3.
  std::map<std::string, size_t> problems;
  std::string note;  ///< e.g. squeue could not be asked

  /// Lines for people: the counts, then the problems, then what to do next.
  std::string Text() const;
};

}  // namespace dream::workflows
