#include "dream/agents/experiments/formation_state_message.h"

#include "dream/agents/framework/byte_reader.h"
#include "dream/agents/framework/byte_writer.h"

namespace dream::agents {

std::vector<uint8_t> FormationStateMessage::Encode() const {
  return ByteWriter()
      .Int32(id)
      .Double(position_m.x())
      .Double(position_m.y())
      .Double(velocity_mps.x())
      .Double(velocity_mps.y())
      .Take();
}

std::optional<FormationStateMessage> FormationStateMessage::Decode(const std::vector<uint8_t>& payload, int sender_id) {
  ByteReader reader(payload);
  FormationStateMessage message;
  message.id = reader.Int32();
  message.position_m.x() = reader.Double();
  message.position_m.y() = reader.Double();
  message.velocity_mps.x() = reader.Double();
  message.velocity_mps.y() = reader.Double();
  if (!reader.done() || message.id != sender_id) return std::nullopt;
  return message;
}

}  // namespace dream::agents
