#pragma once

#include <string>

namespace dream::files {

/// An exclusive lock on an output folder while a command writes it, so two
/// runs given the same folder cannot mix their logs and summaries: flock on
/// the file `.dream.lock` in the folder, which also names the holder (pid and
/// command line). The lock belongs to the process and lasts until it exits
/// (the kernel drops it then, even after SIGKILL); holding a folder again in
/// the same process is a no-op. A child started by a holder (dream launch's
/// simulator) inherits the lock through the descriptor named by the
/// environment variable kInheritedVariable.
class OutputFolderLock {
 public:
  static constexpr const char* kFileName = ".dream.lock";
  static constexpr const char* kInheritedVariable = "DREAM_OUTPUT_LOCK_FD";

  /// Locks the existing folder `dir` until this process exits.
  /// @throws std::runtime_error naming the folder and the process holding it.
  static void HoldUntilExit(const std::string& dir);

  /// HoldUntilExit, but false (and nothing held) when another process holds `dir`.
  static bool TryHoldUntilExit(const std::string& dir);

  /// The descriptor of this process's lock on `dir` (-1 if it holds none),
  /// for a child that must write the folder too.
  static int DescriptorOf(const std::string& dir);
};

}  // namespace dream::files
