#pragma once

#include <string>

namespace dream::workflows {

/// The lock a run folder's `dream run` holds (files::OutputFolderLock's
/// `.dream.lock`, flock), seen from a sweep: whether a run still runs is
/// told by its lock, never by which files are missing. run.sh holds the same
/// lock from before it clears a run until its exit record is written, and
/// hands it to its `dream run` (DREAM_OUTPUT_LOCK_FD).
class RunFolderLock {
 public:
  /// True when another open file holds the lock of the run folder `dir`: a
  /// `dream run` or run.sh works there. Takes the lock shared for an instant
  /// to know (flock has no other test); no lock file, or one that is not a
  /// regular file, holds nothing.
  static bool HeldElsewhere(const std::string& dir);

  /// Takes the lock of `dir` (creating its lock file) while this object
  /// lives, so what is done meanwhile (clearing the run) cannot meet a run
  /// starting there; held() false when another holds it.
  explicit RunFolderLock(const std::string& dir);
  ~RunFolderLock();
  RunFolderLock(const RunFolderLock&) = delete;
  RunFolderLock& operator=(const RunFolderLock&) = delete;

  bool held() const { return held_; }

 private:
  int fd_ = -1;
  bool held_ = false;
};

}  // namespace dream::workflows
