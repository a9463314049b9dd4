#pragma once

#include <string>

namespace dream::files {

/// A folder a command writes its outputs into (a run, an export, a
/// comparison), which no file name can escape: names are
/// plain relative paths without "..", and the real path of what is written
/// (symbolic links resolved) must stay inside the folder. Every file is
/// written atomically (a temporary file in the same folder, then a rename),
/// so a reader sees the old file or the new one, never half of one.
class OutputFolder {
 public:
  /// What to do when the folder's parent is missing. A folder the user named
  /// (--out) must have its parent: a mistyped parent is a mistake to report,
  /// not a tree to create. The exception is one of the folders dream's own
  /// defaults write under (kToolFolders: runs/, sweeps/, exports/ in the
  /// working folder), made when missing as the defaults make them, so
  /// `--out exports/go_to_goal` works in a fresh checkout. A default folder
  /// (runs/<name>) is made with its parents.
  enum class Parents { kMustExist, kCreate };
  static constexpr const char* kToolFolders[] = {"runs", "sweeps", "exports"};

  /// Creates `dir` if missing. @throws std::runtime_error naming the folder.
  explicit OutputFolder(std::string dir, Parents parents = Parents::kMustExist);

  /// `dir/name`, after checking that it stays inside the folder.
  /// @throws std::runtime_error naming the path when it would escape.
  std::string PathOf(const std::string& name) const;

  /// Creates the subfolder `name` (if missing) and returns its path.
  std::string MakeSubfolder(const std::string& name) const;

  /// Removes every file directly in the folder (not subfolders), so that what
  /// it holds next is one command's output only. @throws std::runtime_error
  /// naming a file that cannot be removed and `why` (whose files they were).
  void RemoveFiles(const std::string& why) const;

  /// Writes `bytes` to `name` atomically. @throws std::runtime_error.
  void WriteFile(const std::string& name, const std::string& bytes) const;
  /// The same for a `name` with folders in it (a controller module's
  /// `controllers/orbit.py`): each folder on its way is made first.
  void WriteFileInSubfolders(const std::string& name, const std::string& bytes) const;

  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::string real_dir_;  // canonical path, for the escape check
};

}  // namespace dream::files
