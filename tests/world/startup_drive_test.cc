// The Robotarium's start-up drive (StartupDrive, HybridPoseController): the
// charger slots, the controller's phases, drives that settle and one that
// deadlocks. tests/run_config/startup_drive_configs_test.cc drives the
// shipped configs; tests/bridge compares the stand-in's Python drive with the
// official simulator's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "dream/world/hybrid_pose_controller.h"
#include "dream/world/startup_drive.h"
#include "dream/world/startup_drive_trials.h"

namespace dream::world {
namespace {

using ::testing::HasSubstr;

// Robots 0.2 m apart: the certificate keeps the points 0.05 m ahead of them
// 0.25 m apart, so they can never all stand on these poses.
std::vector<Pose2> CrowdedGrid() {
  std::vector<Pose2> poses;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) poses.push_back({-0.2 + 0.2 * column, -0.2 + 0.2 * row, 0.0});
  }
  return poses;
}

std::vector<Pose2> Spread() {
  return {{-0.8, -0.4, 0.0}, {0.8, 0.4, M_PI}, {-0.8, 0.4, M_PI / 2}, {0.8, -0.4, -M_PI / 2}, {0.0, 0.0, 1.0}};
}

TEST(StartupDriveTest, ChargerSlotsAreElevenPerLongEdgeFacingIn) {
  const std::vector<Pose2> slots = StartupDrive::ChargerSlots(WorldParams{});
  ASSERT_EQ(slots.size(), 22u);
  // width = 3.2 - 0.11, height = 2.0 - 0.11 (rps: arena less one robot diameter)
  EXPECT_DOUBLE_EQ(slots.front().x_m, -3.09 / 2);
  EXPECT_DOUBLE_EQ(slots.back().x_m, 3.09 / 2);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const bool bottom = i % 2 == 0;
    EXPECT_DOUBLE_EQ(slots[i].y_m, bottom ? -1.89 / 2 : 1.89 / 2) << i;
    EXPECT_DOUBLE_EQ(slots[i].theta_rad, bottom ? M_PI / 2 : -M_PI / 2) << i;
  }
  EXPECT_NEAR(slots[2].x_m - slots[0].x_m, 3.09 / 10, 1e-12);
}

TEST(StartupDriveTest, PlacementTakesDistinctSlotsFromTheSeed) {
  const std::vector<Pose2> a = StartupDrive::PlaceOnChargers(WorldParams{}, 22, 7);
  std::set<std::pair<double, double>> seen;
  for (const Pose2& pose : a) seen.insert({pose.x_m, pose.y_m});
  EXPECT_EQ(seen.size(), 22u);
  const std::vector<Pose2> again = StartupDrive::PlaceOnChargers(WorldParams{}, 22, 7);
  const std::vector<Pose2> other = StartupDrive::PlaceOnChargers(WorldParams{}, 22, 8);
  bool same = true;
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    same = same && a[i].x_m == again[i].x_m && a[i].y_m == again[i].y_m;
    differs = differs || a[i].x_m != other[i].x_m || a[i].y_m != other[i].y_m;
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
  EXPECT_THROW(StartupDrive::PlaceOnChargers(WorldParams{}, 23, 7), std::invalid_argument);
}

TEST(HybridPoseControllerTest, ApproachesThenTurnsThenStops) {
  HybridPoseController controller;
  // Far, straight ahead: full approach speed 0.8 * 0.15, no turn.
  UnicycleCommand command = controller.ApplyOne({0, 0, 0}, {1, 0, 0});
  EXPECT_DOUBLE_EQ(command.v_mps, 0.8 * 0.15);
  EXPECT_DOUBLE_EQ(command.w_radps, 0.0);
  // Goal to the left: a quarter turn maps to the angular limit pi/3.
  command = controller.ApplyOne({0, 0, 0}, {0, 1, 0});
  EXPECT_NEAR(command.v_mps, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(command.w_radps, M_PI / 3);
  // On the spot (within 0.02 m) but turned: turn at twice the error.
  command = controller.ApplyOne({0, 0, 0}, {0.01, 0, 0.5});
  EXPECT_DOUBLE_EQ(command.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(command.w_radps, 1.0);
  // Within 0.1 rad: done.
  command = controller.ApplyOne({0, 0, 0}, {0.01, 0, 0.05});
  EXPECT_DOUBLE_EQ(command.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(command.w_radps, 0.0);
}

TEST(HybridPoseControllerTest, KeepsTheApproachFlagOnlyWhileTheRobotCountStays) {
  HybridPoseController controller;
  // Turning 0.03 m from the goal (within 0.05) clears the robot's approach flag ...
  std::vector<UnicycleCommand> commands;
  controller.Apply({{0, 0, 0}, {1, 1, 0}}, {{0.015, 0, 0.5}, {1, 1, 0}}, &commands);
  EXPECT_DOUBLE_EQ(commands[0].v_mps, 0.0);
  // ... so at 0.03 m it keeps turning instead of approaching,
  controller.Apply({{0, 0, 0}, {1, 1, 0}}, {{0.03, 0, 0.5}, {1, 1, 0}}, &commands);
  EXPECT_DOUBLE_EQ(commands[0].v_mps, 0.0);
  EXPECT_DOUBLE_EQ(commands[0].w_radps, 1.0);
  // until a call with another robot count resets the flags (rps's closure does the same).
  controller.ApplyOne({1, 1, 0}, {1, 1, 0});
  controller.Apply({{0, 0, 0}, {1, 1, 0}}, {{0.03, 0, 0.5}, {1, 1, 0}}, &commands);
  EXPECT_GT(commands[0].v_mps, 0.0);
}

TEST(StartupDriveTest, SpreadStartPosesSettleWithinTheLimit) {
  const StartupDrive drive(WorldParams{}, Spread());
  int observed = 0;
  int last_step = 0;
  const StartupDriveResult result = drive.Run(3, [&](int step, const std::vector<Pose2>& poses) {
    ++observed;
    last_step = step;
    EXPECT_EQ(poses.size(), 5u);
  });
  ASSERT_TRUE(result.settled) << result.DescribeMisses();
  EXPECT_TRUE(result.misses.empty());
  EXPECT_GT(result.steps, 1);
  EXPECT_LT(result.steps, StartupDrive::MaxSteps());
  EXPECT_EQ(observed, result.steps);
  EXPECT_EQ(last_step, result.steps);
  ASSERT_EQ(result.final_poses.size(), 5u);
  // The experiment starts near, not on, the start poses (the drive stops within 0.05 m / 0.2 rad,
  // one step later).
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_LT(std::hypot(result.final_poses[i].x_m - Spread()[i].x_m, result.final_poses[i].y_m - Spread()[i].y_m),
              0.06)
        << i;
  }
  // The same seed, the same drive.
  const StartupDriveResult again = drive.Run(3);
  EXPECT_EQ(again.steps, result.steps);
  EXPECT_EQ(again.final_poses[4].x_m, result.final_poses[4].x_m);
}

TEST(StartupDriveTest, CrowdedStartPosesDeadlockAndNameTheRobots) {
  const StartupDrive drive(WorldParams{}, CrowdedGrid());
  const StartupDriveResult result = drive.Run(1);
  EXPECT_FALSE(result.settled);
  EXPECT_EQ(result.steps, StartupDrive::MaxSteps());
  ASSERT_FALSE(result.misses.empty());
  for (const StartupDriveResult::Miss& miss : result.misses) {
    EXPECT_TRUE(miss.distance_m > StartupDrive::kAtPositionM ||
                std::abs(miss.heading_error_rad) > StartupDrive::kAtHeadingRad);
  }
  EXPECT_THAT(result.DescribeMisses(), HasSubstr("robot " + std::to_string(result.misses[0].robot_id) + " "));
}

TEST(StartupDriveTest, ALowerStepLimitIsHonoured) {
  const StartupDriveResult result = StartupDrive(WorldParams{}, Spread(), 20).Run(3);
  EXPECT_FALSE(result.settled);
  EXPECT_EQ(result.steps, 20);
  EXPECT_EQ(result.misses.size(), 5u);
}

TEST(StartupDriveTrialsTest, CountsSettledPlacementsAndDescribesAFailure) {
  const StartupDriveTrials spread = StartupDriveTrials::Try(WorldParams{}, Spread(), 11, 2);
  EXPECT_EQ(spread.tried(), 2);
  EXPECT_TRUE(spread.AllSettled());
  EXPECT_THAT(spread.Describe(), HasSubstr("settled from 2 of 2"));

  const StartupDriveTrials crowded = StartupDriveTrials::Try(WorldParams{}, CrowdedGrid(), 11, 1);
  EXPECT_EQ(crowded.settled(), 0);
  EXPECT_THAT(crowded.Describe(), HasSubstr("settled from 0 of 1"));
  EXPECT_THAT(crowded.Describe(), HasSubstr("after 6000 steps"));
  EXPECT_THAT(crowded.Describe(), HasSubstr(" m / "));
  EXPECT_NE(StartupDriveTrials::PlacementSeed(11, 0), StartupDriveTrials::PlacementSeed(11, 1));
  EXPECT_NE(StartupDriveTrials::PlacementSeed(11, 0), StartupDriveTrials::PlacementSeed(12, 0));
}

TEST(StartupDriveTrialsTest, MoreRobotsThanChargerSlotsCannotStart) {
  std::vector<Pose2> many;
  for (int i = 0; i < 23; ++i) many.push_back({-1.4 + 0.12 * i, 0.0, 0.0});
  const StartupDriveTrials trials = StartupDriveTrials::Try(WorldParams{}, many, 1);
  EXPECT_EQ(trials.tried(), 1);
  EXPECT_FALSE(trials.AllSettled());
  EXPECT_THAT(trials.Describe(), HasSubstr("23 robots do not fit the 22 charger slots"));
}

}  // namespace
}  // namespace dream::world
