// How a lab replay's agents' commands compare with the lab's: the check that
// a controller-strategy submission ran the controllers as DREAM's agents do.
#include "dream/bridge/command_agreement.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dream::bridge {
namespace {

/// Two robots standing apart for `steps` steps; the lab sent robot 0
/// (0.1, 0.2) and robot 1 (0.05, -0.3) at every step.
RunTrack StillTrack(int64_t steps) {
  RunTrack track;
  track.num_robots = 2;
  for (int64_t k = 0; k <= steps; ++k) {
    track.utime.push_back(k * 33000);
    track.poses.push_back({-0.5, 0.0, 0.0});
    track.poses.push_back({0.5, 0.0, 0.0});
    track.commands.push_back({0.1, 0.2});
    track.commands.push_back({0.05, -0.3});
    track.obstacles.emplace_back();
  }
  return track;
}

TEST(CommandAgreementTest, AgentsThatSendTheLabsCommandsAgreeWithinRounding) {
  LabReplayWorld replay(StillTrack(3), world::WorldParams{});
  for (int k = 0; k < 3; ++k) {
    replay.SetCommand(0, {0.1, 0.2 + 1e-13});  // the last bits of another numpy build
    replay.SetCommand(1, {0.05, -0.3});
    replay.Step();
  }
  const CommandAgreement agreement = CommandAgreement::Of(replay);
  EXPECT_EQ(agreement.steps(), 3);
  EXPECT_TRUE(agreement.Same());
  EXPECT_TRUE(agreement.Complete());
  ASSERT_EQ(agreement.robots().size(), 2u);
  EXPECT_EQ(agreement.robots()[0].v_mps.count(), 3);
  EXPECT_NEAR(agreement.robots()[0].w_radps.max(), 1e-13, 1e-15);
  EXPECT_EQ(agreement.robots()[0].first_different_step, -1);
}

TEST(CommandAgreementTest, TheFirstDifferentStepAndTheWorstRobotAreNamed) {
  LabReplayWorld replay(StillTrack(4), world::WorldParams{});
  const double robot1_w[] = {-0.3, -0.3, -0.1, -0.4};  // differs from step 2: 0.2, then 0.1
  for (int k = 0; k < 4; ++k) {
    replay.SetCommand(0, {0.1, 0.2});
    replay.SetCommand(1, {0.05, robot1_w[k]});
    replay.Step();
  }
  const CommandAgreement agreement = CommandAgreement::Of(replay);
  EXPECT_FALSE(agreement.Same());
  EXPECT_TRUE(agreement.Complete());
  EXPECT_EQ(agreement.WorstRobot(), 1);
  const CommandAgreement::RobotAgreement& robot = agreement.robots()[1];
  EXPECT_EQ(robot.first_different_step, 2);
  EXPECT_NEAR(robot.w_radps.max(), 0.2, 1e-12);
  EXPECT_EQ(robot.w_radps.max_step(), 2);
  EXPECT_NEAR(robot.w_radps.Rms(), std::sqrt((0.04 + 0.01) / 4.0), 1e-12);
  EXPECT_EQ(robot.v_mps.max(), 0.0);
  EXPECT_NEAR(agreement.MaxWDifference(), 0.2, 1e-12);
  EXPECT_EQ(agreement.MaxVDifference(), 0.0);
  const nlohmann::ordered_json json = agreement.Json();
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[1]["robot"], 1);
  EXPECT_EQ(json[1]["first_different_step"], 2);
  EXPECT_EQ(json[1]["steps_with_command"], 4);
  EXPECT_EQ(json[0]["first_different_step"], -1);
}

TEST(CommandAgreementTest, AnAgentThatFellSilentLeavesTheRunIncompleteButNotDifferent) {
  LabReplayWorld replay(StillTrack(3), world::WorldParams{});
  replay.SetCommand(0, {0.1, 0.2});
  replay.SetCommand(1, {0.05, -0.3});
  replay.Step();
  replay.StopRobot(1);  // its controller failed: no command from step 1 on
  replay.SetCommand(0, {0.1, 0.2});
  replay.Step();
  replay.SetCommand(0, {0.1, 0.2});
  replay.Step();
  const CommandAgreement agreement = CommandAgreement::Of(replay);
  EXPECT_TRUE(agreement.Same());
  EXPECT_FALSE(agreement.Complete());
  EXPECT_EQ(agreement.robots()[1].v_mps.count(), 1);
  EXPECT_EQ(agreement.robots()[0].v_mps.count(), 3);
}

TEST(CommandAgreementTest, BeforeTheFirstStepThereIsNothingToCompare) {
  const LabReplayWorld replay(StillTrack(2), world::WorldParams{});
  const CommandAgreement agreement = CommandAgreement::Of(replay);
  EXPECT_EQ(agreement.steps(), 0);
  EXPECT_TRUE(agreement.Same());
  EXPECT_TRUE(agreement.Complete());
  EXPECT_EQ(agreement.robots()[0].v_mps.Rms(), 0.0);
  EXPECT_EQ(agreement.robots()[0].v_mps.max_step(), -1);
}

}  // namespace
}  // namespace dream::bridge
