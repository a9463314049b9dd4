#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dream/formats/npy_file.h"

namespace dream::formats {

/// A numpy .npz file (numpy.savez or savez_compressed: a zip archive of
/// NAME.npy members, stored or deflated), read through libzip.
class NpzFile {
 public:
  /// @throws std::runtime_error naming the path when it is no zip archive.
  explicit NpzFile(std::string path);
  ~NpzFile();
  NpzFile(const NpzFile&) = delete;
  NpzFile& operator=(const NpzFile&) = delete;

  /// The array saved as `name` (member NAME.npy), decoded as DecodeNpy does;
  /// none when there is no such member. A member declaring more than
  /// `max_bytes` uncompressed is refused before anything is inflated, and one
  /// that inflates to another size than it declares, or fails its CRC, is an
  /// error. @throws std::runtime_error naming the path and the member.
  std::optional<NpyArray> Read(const std::string& name, int64_t max_bytes) const;

  /// The names of its members without ".npy" (for "no array 'x'; it holds ...").
  std::vector<std::string> Names() const;

 private:
  std::string path_;
  void* archive_ = nullptr;  // zip_t*
};

}  // namespace dream::formats
