#pragma once

#include <cstdint>
#include <string>

namespace dream::files {

/// A file opened for reading that is known to be a regular file. Opening never
/// waits: the path is opened without blocking and the opened descriptor (not
/// the path, which could be swapped in between) is asked what it is, so a
/// FIFO, device, socket or folder given where a file is expected is refused
/// with its name instead of hanging the command in open() deaf to Ctrl-C.
/// Every file dream reads from a path it was given goes through here.
class RegularFile {
 public:
  /// @throws std::runtime_error naming the path when it cannot be opened or
  ///         is not a regular file.
  explicit RegularFile(std::string path);
  ~RegularFile();
  RegularFile(RegularFile&& other) noexcept;
  RegularFile& operator=(RegularFile&&) = delete;
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  /// Its size when opened.
  std::uintmax_t size() const { return size_; }
  const std::string& path() const { return path_; }
  /// The open descriptor (blocking reads), owned by this object.
  int descriptor() const { return fd_; }
  /// A name of this very file (/proc/self/fd/N) for a library that opens by
  /// name (libmatio, HDF5): it reopens what was checked, whatever the path
  /// names meanwhile. Valid while this object lives.
  std::string OpenedName() const;

  /// Everything from the current offset to the end, of at most `max_bytes`.
  /// @throws std::runtime_error naming the path (and the size, when too large).
  std::string ReadAll(std::uintmax_t max_bytes);

 private:
  std::string path_;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
};

}  // namespace dream::files
