#pragma once

#include <string>

namespace dream::bridge {

/// A folder the bridge writes into, which no file name can escape: names are
/// plain relative paths without "..", and the real path of what is written
/// (symbolic links resolved) must stay inside the folder. Every file is
/// written atomically (a temporary file in the same folder, then a rename),
/// so a reader sees the old file or the new one, never half of one.
class OutputFolder {
 public:
  /// Creates `dir` if missing; its parent folder must exist.
  /// @throws std::runtime_error naming the folder.
  explicit OutputFolder(std::string dir);

  /// `dir/name`, after checking that it stays inside the folder.
  /// @throws std::runtime_error naming the path when it would escape.
  std::string PathOf(const std::string& name) const;

  /// Creates the subfolder `name` (if missing) and returns its path.
  std::string MakeSubfolder(const std::string& name) const;

  /// Writes `bytes` to `name` atomically. @throws std::runtime_error.
  void WriteFile(const std::string& name, const std::string& bytes) const;

  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::string real_dir_;  // canonical path, for the escape check
};

/// Throws std::runtime_error when `name` is not a plain relative path that
/// stays below its folder (empty, absolute, "..", or a NUL byte).
void CheckRelativeName(const std::string& name);

}  // namespace dream::bridge
