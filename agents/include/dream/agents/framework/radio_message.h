#pragma once

#include <cstdint>
#include <vector>

namespace dream::agents {

/// One radio broadcast: who sent it, at which step, and the algorithm's own
/// payload (encode it with ByteWriter, decode with ByteReader).
struct RadioMessage {
  int sender_id = 0;
  int64_t sent_step = 0;
  std::vector<uint8_t> payload;
};

}  // namespace dream::agents
