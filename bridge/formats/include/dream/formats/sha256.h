#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace dream::formats {

/// SHA-256 (FIPS 180-4), for the digests of an export's upload files: fed
/// in pieces, so a file is hashed without holding it in memory.
class Sha256 {
 public:
  Sha256();

  /// Hashes `bytes` after everything given before.
  void Add(std::string_view bytes);
  /// The digest of everything added, as 64 lowercase hex digits; ends the hash.
  std::string HexDigest();

  /// The digest of `bytes`.
  static std::string Hex(std::string_view bytes);
  /// The digest of the file at `path`, read in blocks.
  /// @throws std::runtime_error naming the file when it cannot be read.
  static std::string HexOfFile(const std::string& path);

 private:
  void Block(const uint8_t* block);

  uint32_t state_[8];
  uint8_t buffer_[64];
  size_t buffered_ = 0;
  uint64_t length_bytes_ = 0;
};

}  // namespace dream::formats
