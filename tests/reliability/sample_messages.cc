#include "sample_messages.h"

#include "../support/sample_lcm_messages.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::testing {

std::vector<EncodedMessage> SampleMessages() {
  return {{"robot_poses_t", Encoded(SamplePoses())},
          {"obstacles_t", Encoded(SampleObstacles())},
          {"run_status_t", Encoded(SampleRunStatus())},
          {"velocity_command_t", Encoded(SampleCommand())},
          {"radio_message_t", Encoded(SampleRadioMessage())},
          {"robot_fault_t", Encoded(SampleFault())},
          {"applied_commands_t", Encoded(SampleAppliedCommands())},
          {"run_verdict_t", Encoded(SampleVerdict())},
          {"drawing_t", Encoded(SampleDrawing())},
          {"robot_busy_t", Encoded(SampleBusy())},
          {"robot_commands_t", Encoded(SampleCommandBatch())}};
}

namespace {

template <typename Message>
TypedDecoder DecoderOf() {
  return [](const uint8_t* data, int size) {
    Message message;
    return lcm::Decode(data, size, &message);
  };
}

}  // namespace

const std::map<std::string, TypedDecoder>& Decoders() {
  static const std::map<std::string, TypedDecoder> decoders = {
      {"robot_poses_t", DecoderOf<robot_poses_t>()},
      {"obstacles_t", DecoderOf<obstacles_t>()},
      {"run_status_t", DecoderOf<run_status_t>()},
      {"velocity_command_t", DecoderOf<velocity_command_t>()},
      {"radio_message_t", DecoderOf<radio_message_t>()},
      {"robot_fault_t", DecoderOf<robot_fault_t>()},
      {"applied_commands_t", DecoderOf<applied_commands_t>()},
      {"run_verdict_t", DecoderOf<run_verdict_t>()},
      {"drawing_t", DecoderOf<drawing_t>()},
      {"robot_busy_t", DecoderOf<robot_busy_t>()},
      {"robot_commands_t", DecoderOf<robot_commands_t>()},
  };
  return decoders;
}

}  // namespace dream::testing
