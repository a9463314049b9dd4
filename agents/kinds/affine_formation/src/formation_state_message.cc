#include "dream/affine_formation/formation_state_message.h"

#include "dream/agents/framework/byte_reader.h"
#include "dream/agents/framework/byte_writer.h"

namespace dream::affine_formation {

std::vector<uint8_t> FormationStateMessage::Encode() const {
  return agents::ByteWriter().Int32(id).Vector2(position_m).Vector2(velocity_mps).Take();
}

std::optional<FormationStateMessage> FormationStateMessage::Decode(const std::vector<uint8_t>& payload, int sender_id) {
  agents::ByteReader reader(payload);
  FormationStateMessage message;
  message.id = reader.Int32();
  message.position_m = reader.Vector2();
  message.velocity_mps = reader.Vector2();
  if (!reader.done() || message.id != sender_id) return std::nullopt;
  return message;
}

}  // namespace dream::affine_formation
