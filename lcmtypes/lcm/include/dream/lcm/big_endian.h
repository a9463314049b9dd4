#pragma once

#include <cstddef>
#include <cstdint>

namespace dream::lcm {

/// The unsigned big-endian integer of `count` (at most 8) bytes at `data`: LCM's
/// byte order, for its log files, its messages' headers and the Python relay's
/// frames. The caller has checked that the bytes are there.
inline uint64_t BigEndianAt(const void* data, size_t count) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  uint64_t value = 0;
  for (size_t i = 0; i < count; ++i) value = (value << 8) | bytes[i];
  return value;
}

}  // namespace dream::lcm
