#include "dream/lcm/message_header.h"

#include "dream/lcm/big_endian.h"

namespace dream::lcm {

int64_t MessageHeader::Int64At(const void* data, size_t at) {
  return static_cast<int64_t>(BigEndianAt(static_cast<const unsigned char*>(data) + at, 8));
}

std::optional<MessageHeader> MessageHeader::Read(const void* data, size_t size) {
  if (data == nullptr || size < kBytes) return std::nullopt;
  MessageHeader header;
  header.fingerprint = Int64At(data, kFingerprintAt);
  header.utime = Int64At(data, kUtimeAt);
  header.step = Int64At(data, kStepAt);
  header.run_id = Int64At(data, kRunIdAt);
  return header;
}

std::optional<int64_t> MessageHeader::AgentIdOf(const void* data, size_t size) {
  if (data == nullptr || size < kAgentIdAt + 8) return std::nullopt;
  return Int64At(data, kAgentIdAt);
}

}  // namespace dream::lcm
