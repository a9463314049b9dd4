#pragma once

#include <cstdint>
#include <string>

namespace dream::formats {

/// Walks the variables of a MATLAB v4 file (no header: each variable is a
/// 20-byte header, its name and its data) against the bytes it has. libmatio
/// trusts a v4 header's name length and rows x columns and allocates them
/// before reading, so 40 bytes of anything could make it ask for gigabytes;
/// a file that is not v5 or v7.3 must be a sound v4 file before it gets there.
class Mat4Layout {
 public:
  /// `path` (for errors) and `bytes` must outlive the layout.
  Mat4Layout(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

  /// @throws std::runtime_error naming the file, the variable and its byte offset.
  void Check() const;

  /// Whether libmatio's v4 reader would take the first word for a type code
  /// (0..4052 in either byte order) and go on to read and allocate: it falls
  /// back to v4 when a v7.3 file's HDF5 part does not open.
  static bool ReadableAsV4(const std::string& bytes);

 private:
  static constexpr uint64_t kHeaderBytes = 20;
  static constexpr int32_t kMaxNameBytes = 4096;  // MATLAB names have at most 63 characters

  [[noreturn]] void Fail(const std::string& problem) const;
  int32_t Word(uint64_t offset, bool swap) const;
  /// Checks variable `index` at `offset`; returns the offset after it.
  uint64_t CheckVariable(int index, uint64_t offset) const;

  const std::string& path_;
  const std::string& bytes_;
};

}  // namespace dream::formats
