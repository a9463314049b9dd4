#include "dream/agents/framework/position_message.h"

#include "dream/agents/framework/byte_reader.h"
#include "dream/agents/framework/byte_writer.h"

namespace dream::agents {

std::vector<uint8_t> PositionMessage::Encode() const { return ByteWriter().Int32(id).Vector2(position_m).Take(); }

std::optional<PositionMessage> PositionMessage::Decode(const std::vector<uint8_t>& payload, int sender_id) {
  ByteReader reader(payload);
  PositionMessage message;
  message.id = reader.Int32();
  message.position_m = reader.Vector2();
  if (!reader.done() || message.id != sender_id) return std::nullopt;
  return message;
}

}  // namespace dream::agents
