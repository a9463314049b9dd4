#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "../support/encoded_message.h"
#include "../support/sample_lcm_messages.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/run_id.h"

namespace dream::lcm {
namespace {

using dream::testing::Encoded;
using dream::testing::SampleAppliedCommands;
using dream::testing::SampleCommand;
using dream::testing::SampleCommandBatch;
using dream::testing::SampleDrawing;
using dream::testing::SamplePoses;

template <typename Message>
Message Decoded(const std::vector<uint8_t>& bytes) {
  Message message;
  EXPECT_TRUE(Decode(bytes.data(), static_cast<int>(bytes.size()), &message));
  return message;
}

// The samples carry a run id and an agent id (kSampleRunId, kSampleAgentId): what is cleared.
TEST(RandomIdsTest, CommandLosesRunAndAgentIdsKeepsTheRest) {
  const velocity_command_t command = SampleCommand();
  std::vector<uint8_t> bytes = Encoded(command);
  ClearRandomIds(&bytes);
  const velocity_command_t cleared = Decoded<velocity_command_t>(bytes);
  EXPECT_EQ(cleared.run_id, 0);
  EXPECT_EQ(cleared.agent_id, 0);
  EXPECT_EQ(cleared.step, command.step);
  EXPECT_EQ(cleared.robot_id, command.robot_id);
  EXPECT_EQ(cleared.v, command.v);
  EXPECT_EQ(cleared.w, command.w);
}

TEST(RandomIdsTest, AppliedCommandsLoseEveryAgentId) {
  const applied_commands_t applied = SampleAppliedCommands();
  ASSERT_NE(applied.applied_agent_id[0], 0);
  std::vector<uint8_t> bytes = Encoded(applied);
  ClearRandomIds(&bytes);
  const applied_commands_t cleared = Decoded<applied_commands_t>(bytes);
  EXPECT_EQ(cleared.run_id, 0);
  EXPECT_EQ(cleared.applied_agent_id, (std::vector<int64_t>{0, 0}));
  EXPECT_EQ(cleared.conflicts, applied.conflicts);
}

TEST(RandomIdsTest, DrawingsAndCommandBatchesLoseRunAndAgentIds) {
  const drawing_t drawing = SampleDrawing();
  std::vector<uint8_t> bytes = Encoded(drawing);
  ClearRandomIds(&bytes);
  const drawing_t cleared = Decoded<drawing_t>(bytes);
  EXPECT_EQ(cleared.run_id, 0);
  EXPECT_EQ(cleared.agent_id, 0);
  EXPECT_EQ(cleared.robot_id, drawing.robot_id);
  EXPECT_EQ(cleared.x, drawing.x);

  const robot_commands_t batch = SampleCommandBatch();
  bytes = Encoded(batch);
  ClearRandomIds(&bytes);
  const robot_commands_t cleared_batch = Decoded<robot_commands_t>(bytes);
  EXPECT_EQ(cleared_batch.run_id, 0);
  EXPECT_EQ(cleared_batch.agent_id, 0);
  EXPECT_EQ(cleared_batch.w, batch.w);
}

TEST(RandomIdsTest, PosesLoseTheRunIdOnlyAndOtherBytesStayAsTheyAre) {
  const robot_poses_t poses = SamplePoses();
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
