#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace dream::testing {

/// One encoded dream message and the name of its type.
struct EncodedMessage {
  std::string type;
  std::vector<uint8_t> bytes;
};

/// Real encoded messages of every dream type, with every variable-length
/// field non-empty (the seeds the forgery and mutation tests start from).
std::vector<EncodedMessage> SampleMessages();

/// lcm::Decode() for each dream type, by type name: true when the bytes decoded.
using TypedDecoder = std::function<bool(const uint8_t* data, int size)>;
const std::map<std::string, TypedDecoder>& Decoders();

/// Encodes an lcm-gen message.
template <typename Message>
std::vector<uint8_t> Encoded(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace dream::testing
