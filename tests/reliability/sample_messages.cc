#include "sample_messages.h"

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
  constexpr int64_t kRunId = 0x5eed0000c0ffee;
  robot_poses_t poses{};
  poses.step = 3;
  poses.run_id = kRunId;
  poses.num_robots = 2;
  poses.x = {0.1, -0.2};
  poses.y = {0.3, 0.4};
  poses.theta = {0.0, 1.0};
  poses.v = {0.05, 0.0};
  poses.w = {0.0, -0.5};

  obstacles_t obstacles{};
  obstacles.step = 3;
  obstacles.run_id = kRunId;
  obstacles.num_obstacles = 2;
  obstacles.obstacles.resize(2);
  obstacles.obstacles[1].id = 1;
  obstacles.obstacles[1].width = 0.2;

  run_status_t status{};
  status.step = 3;
  status.run_id = kRunId;
  status.command_conflicts = 2;
  status.state = run_status_t::RUNNING;
  status.num_robots = 2;
  status.num_lost = 1;
  status.lost_robot_ids = {1};
  status.detail = "robot 1 is silent";

  velocity_command_t command{};
  command.step = 3;
  command.run_id = kRunId;
  command.robot_id = 1;
  command.agent_id = 0x1234567890;
  command.v = 0.1;

  radio_message_t radio{};
  radio.step = 3;
  radio.run_id = kRunId;
  radio.sender_id = 1;
  radio.agent_id = 0x1234567890;
  radio.payload = {1, 2, 3, 4, 5};
  radio.payload_size = 5;

  robot_fault_t fault{};
  fault.step = 3;
  fault.run_id = kRunId;
  fault.robot_id = 1;
  fault.agent_id = 0x1234567890;
  fault.detail = "controller.py:12: in update: ValueError: boom";

  applied_commands_t applied{};
  applied.step = 3;
  applied.run_id = kRunId;
  applied.num_robots = 2;
  applied.applied_agent_id = {0x1234567890, 0};
  applied.commanded_v = {0.1, 0.0};
  applied.commanded_w = {-0.5, 0.0};
  applied.conflicts = {1, 0};

  run_verdict_t verdict{};
  verdict.step = 3;
  verdict.run_id = kRunId;
  verdict.verdict = run_verdict_t::NOT_READY;
  verdict.goal = run_verdict_t::GOAL_MISSED;
  verdict.exit_code = 5;
  verdict.goal_completion_step = -1;
  verdict.goal_text = "missed (1 of 2 robots arrived)";
  verdict.reasons = "goal: the go_to_goal experiment missed its goal";

  drawing_t drawing{};
  drawing.step = 3;
  drawing.run_id = kRunId;
  drawing.robot_id = 1;
  drawing.agent_id = 0x1234567890;
  drawing.num_shapes = 2;
  drawing.kind = {drawing_t::LINE, drawing_t::TEXT};
  drawing.rgba = {static_cast<int32_t>(0xff0000ffu), 0x000000ff};
  drawing.width = {0.01, 0.0};
  drawing.size = {0.0, 0.05};
  drawing.fill = {0, 0};
  drawing.point_count = {2, 1};
  drawing.text_length = {0, 2};
  drawing.num_points = 3;
  drawing.x = {0.0, 1.0, -0.5};
  drawing.y = {0.0, 0.5, 0.5};
  drawing.num_text_bytes = 2;
  drawing.text = {'h', 'i'};
  robot_busy_t busy{};
  busy.step = 3;
  busy.run_id = kRunId;
  busy.robot_id = 1;
  busy.agent_id = 0x1234567890;
  busy.call_robot_id = 0;
  busy.call_s = 0.25;
  robot_commands_t commands{};
  commands.step = 3;
  commands.run_id = kRunId;
  commands.agent_id = 0x1234567890;
  commands.num_commands = 2;
  commands.robot_id = {1, 0};
  commands.v = {0.1, -0.05};
  commands.w = {0.5, 0.0};
  commands.done = {0, 1};

  return {{"robot_poses_t", Encoded(poses)},        {"obstacles_t", Encoded(obstacles)},
          {"run_status_t", Encoded(status)},        {"velocity_command_t", Encoded(command)},
          {"radio_message_t", Encoded(radio)},      {"robot_fault_t", Encoded(fault)},
          {"applied_commands_t", Encoded(applied)}, {"run_verdict_t", Encoded(verdict)},
          {"drawing_t", Encoded(drawing)},          {"robot_busy_t", Encoded(busy)},
          {"robot_commands_t", Encoded(commands)}};
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
