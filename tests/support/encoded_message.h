#pragma once

#include <cstdint>
#include <vector>

namespace dream::testing {

/// An lcm-gen message's bytes, as the bus would carry them.
template <typename Message>
std::vector<uint8_t> Encoded(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace dream::testing
