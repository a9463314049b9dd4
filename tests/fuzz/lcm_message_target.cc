#include <cstdint>
#include <cstring>
#include <vector>

#include "dream/affine_formation/formation_state_message.h"
#include "dream/agents/framework/position_message.h"
#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/lcm/drawing_shapes.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/wire_layout_of.h"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "fuzz_targets.h"

namespace dream::fuzz {
namespace {

// A message the bounds check lets through must decode and encode back to
// exactly its bytes: anything else is a check too loose for lcm-gen's code.
template <typename Message>
void Decode(const std::vector<uint8_t>& bytes) {
  const int size = static_cast<int>(bytes.size());
  (void)lcm::WireLayoutOf<Message>().AgentIdOf(bytes.data(), size);
  Message message;
  if (lcm::DecodeProblem(bytes.data(), size, &message)) return;
  std::vector<uint8_t> again(bytes.size());
  if (message.getEncodedSize() != size || message.encode(again.data(), 0, size) != size ||
      std::memcmp(again.data(), bytes.data(), bytes.size()) != 0) {
    Finding(std::string("a ") + Message::getTypeName() + " accepted by its layout does not encode back to its bytes");
  }
}

// A drawing_t the layout lets through, then read as shapes as the world, the view and pictures
// read it: whatever its counts and offsets say, nothing is read past its arrays.
void DecodeDrawing(const std::vector<uint8_t>& bytes) {
  Decode<drawing_t>(bytes);
  drawing_t message;
  if (lcm::DecodeProblem(bytes.data(), static_cast<int>(bytes.size()), &message)) return;
  const std::string problem = lcm::DrawingShapes::Problem(message);
  const std::vector<lcm::DrawnShape> shapes = lcm::DrawingShapes::Of(message);
  if (problem.empty() ? shapes.size() != message.kind.size() : !shapes.empty()) {
    Finding("DrawingShapes::Of disagrees with Problem");
  }
}

}  // namespace

void LcmMessageTarget(const uint8_t* data, size_t size) {
  if (size < 1 || size > (size_t{1} << 20)) return;
  // A copy of exactly the message's bytes, so ASan sees any read past them.
  const std::vector<uint8_t> bytes(data + 1, data + size);
  switch (data[0] % 12) {
    case 0:
      Decode<applied_commands_t>(bytes);
      break;
    case 1:
      Decode<obstacles_t>(bytes);
      break;
    case 2:
      Decode<radio_message_t>(bytes);
      break;
    case 3:
      Decode<robot_fault_t>(bytes);
      break;
    case 4:
      Decode<robot_poses_t>(bytes);
      break;
    case 5:
      Decode<run_status_t>(bytes);
      break;
    case 6:
      Decode<velocity_command_t>(bytes);
      break;
    case 7:
      Decode<run_verdict_t>(bytes);
      break;
    case 8:
      DecodeDrawing(bytes);
      break;
    case 9:
      Decode<robot_busy_t>(bytes);
      break;
    case 10:
      Decode<robot_commands_t>(bytes);
      break;
    default:
      (void)agents::PositionMessage::Decode(bytes, 1);
      (void)affine_formation::FormationStateMessage::Decode(bytes, 1);
  }
}

}  // namespace dream::fuzz
