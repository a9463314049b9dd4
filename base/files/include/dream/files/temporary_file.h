#pragma once

#include <string>

namespace dream::files {

/// A new file beside `target` (`target.tmp.XXXXXXXX`, an unguessable name)
/// that becomes `target` by a rename, so a reader sees the old file or the
/// new one, never half of one. It is created exclusively (O_CREAT | O_EXCL |
/// O_NOFOLLOW): a file or symbolic link planted at a temporary name in a
/// shared folder is never opened, truncated or written through; the name is
/// drawn again instead. Removed when destroyed before Commit().
class TemporaryFile {
 public:
  /// @throws std::runtime_error naming `target` when no file can be created
  ///         beside it (a missing folder, no permission, a full disk).
  /// `suffix` ends the temporary name (".png": for a program that tells a
  /// file's format by its name).
  explicit TemporaryFile(std::string target, const std::string& suffix = "");
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  /// The temporary file's name, for a program that writes it by name (ffmpeg).
  const std::string& path() const { return path_; }
  /// Its descriptor, open for writing, owned by this object.
  int descriptor() const { return fd_; }

  /// Writes all of `bytes` at the current offset. @throws std::runtime_error naming the target.
  void Write(const std::string& bytes);
  /// Syncs the file to disk (before Commit: the renamed file is whole after a power cut).
  void Sync();
  /// Closes the file and renames it over the target. @throws std::runtime_error naming it.
  void Commit();

 private:
  [[noreturn]] void Fail(const std::string& reason);

  std::string target_;
  std::string path_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace dream::files
