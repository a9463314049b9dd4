#pragma once

#include <string>

namespace dream::files {

/// The folder a command that records a run (dream run, sim, launch,
/// lab-replay, import) writes into, chosen so that a rerun never overwrites
/// an earlier run silently:
///  - without --out, the default folder (runs/<name>), or when that already
///    holds a run the first free one of runs/<name>_2, _3, ..., said in one line;
///  - with --out, that folder, refused while it holds a run;
///  - with --overwrite, the folder (given or default) even when it holds a
///    run, whose run.lcmlog, summary.json and trajectories.png are removed
///    first so they cannot pass for the new run's.
/// A run killed before it ended leaves run.lcmlog.part: that folder holds a
/// run too (its log is refused to a rerun, not truncated by it).
/// The chosen folder is created (a default one with its parents, a given
/// one only when its parent exists, as files::OutputFolder does), or with
/// kLater only a default folder's parents: for a command that checks its
/// input first and must leave no folder when it refuses it (dream import).
class RunFolderChoice {
 public:
  enum class Create { kNow, kLater };

  /// @throws std::runtime_error naming the folder and the ways out
  ///         (--overwrite, another --out), or why it cannot be created.
  RunFolderChoice(const std::string& out, const std::string& default_dir, bool overwrite, Create create = Create::kNow);

  /// True when `dir` holds a run's outputs: a file run.lcmlog, summary.json
  /// or run.lcmlog.part (a run that did not end).
  static bool HoldsRun(const std::string& dir);

  /// The folder to write into.
  const std::string& dir() const { return dir_; }
  /// True when the default folder was taken and a numbered one chosen.
  bool renamed() const { return renamed_; }

 private:
  std::string dir_;
  bool renamed_ = false;
};

}  // namespace dream::files
