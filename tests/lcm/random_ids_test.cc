#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/run_id.h"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "../support/encoded_message.h"

namespace dream::lcm {
namespace {

using dream::testing::Encoded;

template <typename Message>
Message Decoded(const std::vector<uint8_t>& bytes) {
  Message message;
  EXPECT_TRUE(Decode(bytes.data(), static_cast<int>(bytes.size()), &message));
  return message;
}

TEST(RandomIdsTest, CommandLosesRunAndAgentIdsKeepsTheRest) {
  velocity_command_t command{};
  command.step = 12;
  command.run_id = 0x1234;
  command.robot_id = 3;
  command.agent_id = 987654321;
  command.v = 0.1;
  command.w = -0.5;
  std::vector<uint8_t> bytes = Encoded(command);
  ClearRandomIds(&bytes);
  const velocity_command_t cleared = Decoded<velocity_command_t>(bytes);
  EXPECT_EQ(cleared.run_id, 0);
  EXPECT_EQ(cleared.agent_id, 0);
  EXPECT_EQ(cleared.step, 12);
  EXPECT_EQ(cleared.robot_id, 3);
  EXPECT_EQ(cleared.v, 0.1);
  EXPECT_EQ(cleared.w, -0.5);
}

TEST(RandomIdsTest, AppliedCommandsLoseEveryAgentId) {
  applied_commands_t applied{};
  applied.run_id = 77;
  applied.num_robots = 2;
  applied.applied_agent_id = {11, 0};
  applied.commanded_v = {0.1, 0.0};
  applied.commanded_w = {0.2, 0.0};
  applied.conflicts = {1, 0};
  std::vector<uint8_t> bytes = Encoded(applied);
  ClearRandomIds(&bytes);
  const applied_commands_t cleared = Decoded<applied_commands_t>(bytes);
  EXPECT_EQ(cleared.run_id, 0);
  EXPECT_EQ(cleared.applied_agent_id, (std::vector<int64_t>{0, 0}));
  EXPECT_EQ(cleared.conflicts, (std::vector<int32_t>{1, 0}));
}

TEST(RandomIdsTest, DrawingsAndCommandBatchesLoseRunAndAgentIds) {
  drawing_t drawing{};
  drawing.step = 4;
  drawing.run_id = 0x77;
  drawing.robot_id = 2;
  drawing.agent_id = 123456;
  drawing.num_shapes = 1;
  drawing.kind = {drawing_t::CIRCLE};
  drawing.rgba = {255};
  drawing.width = {0.01};
  drawing.size = {0.1};
  drawing.fill = {0};
  drawing.point_count = {1};
  drawing.text_length = {0};
  drawing.num_points = 1;
  drawing.x = {0.5};
  drawing.y = {-0.5};
  std::vector<uint8_t> bytes = Encoded(drawing);
  ClearRandomIds(&bytes);
  const drawing_t cleared = Decoded<drawing_t>(bytes);
  EXPECT_EQ(cleared.run_id, 0);
  EXPECT_EQ(cleared.agent_id, 0);
  EXPECT_EQ(cleared.robot_id, 2);
  EXPECT_EQ(cleared.x, drawing.x);

  robot_commands_t batch{};
  batch.step = 4;
  batch.run_id = 0x77;
  batch.agent_id = 654321;
  batch.num_commands = 2;
  batch.robot_id = {0, 1};
  batch.v = {0.1, 0.2};
  batch.w = {0.0, -0.3};
  batch.done = {false, true};
  bytes = Encoded(batch);
  ClearRandomIds(&bytes);
  const robot_commands_t cleared_batch = Decoded<robot_commands_t>(bytes);
  EXPECT_EQ(cleared_batch.run_id, 0);
  EXPECT_EQ(cleared_batch.agent_id, 0);
  EXPECT_EQ(cleared_batch.w, batch.w);
}

TEST(RandomIdsTest, PosesLoseTheRunIdOnlyAndOtherBytesStayAsTheyAre) {
  robot_poses_t poses{};
  poses.run_id = 5;
  poses.num_robots = 1;
  poses.x = {0.25};
  poses.y = {-0.5};
  poses.theta = {1.0};
  poses.v = {0.0};
  poses.w = {0.0};
  std::vector<uint8_t> bytes = Encoded(poses);
  ClearRandomIds(&bytes);
  EXPECT_EQ(Decoded<robot_poses_t>(bytes).run_id, 0);
  EXPECT_EQ(Decoded<robot_poses_t>(bytes).x, poses.x);

  std::vector<uint8_t> garbage(40, 0xAB);
  const std::vector<uint8_t> before = garbage;
  ClearRandomIds(&garbage);
  EXPECT_EQ(garbage, before);
}

}  // namespace
}  // namespace dream::lcm
