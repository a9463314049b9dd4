#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "../support/encoded_message.h"

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

}  // namespace dream::testing
