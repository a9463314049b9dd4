#include "dream/sim/initial_pose_generator.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dream/sim/unicycle_world.h"

namespace dream::sim {
namespace {

using ::testing::HasSubstr;

constexpr double kPi = 3.14159265358979323846;

std::string GenerateError(const WorldParams& world, const InitialPoseParams& params, int num_robots) {
  try {
    InitialPoseGenerator(world, params).Generate(num_robots, 1);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(InitialPoseGeneratorTest, SameSeedSamePosesOtherSeedOtherPoses) {
  const InitialPoseGenerator generator(WorldParams{}, InitialPoseParams{});
  const std::vector<Pose2> a = generator.Generate(30, 42);
  const std::vector<Pose2> b = generator.Generate(30, 42);
  const std::vector<Pose2> c = generator.Generate(30, 43);
  ASSERT_EQ(a.size(), 30u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x_m, b[i].x_m);
    EXPECT_EQ(a[i].y_m, b[i].y_m);
    EXPECT_EQ(a[i].theta_rad, b[i].theta_rad);
  }
  EXPECT_NE(a[0].x_m, c[0].x_m);
}

TEST(InitialPoseGeneratorTest, FiftyRobotsInsideSpacedAndCollisionFree) {
  const WorldParams world;
  const InitialPoseParams params;
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const std::vector<Pose2> poses = InitialPoseGenerator(world, params).Generate(50, seed);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      EXPECT_GE(poses[i].x_m, world.arena.x_min_m + params.wall_margin_m);
      EXPECT_LE(poses[i].x_m, world.arena.x_max_m - params.wall_margin_m);
      EXPECT_GE(poses[i].y_m, world.arena.y_min_m + params.wall_margin_m);
      EXPECT_LE(poses[i].y_m, world.arena.y_max_m - params.wall_margin_m);
      EXPECT_GE(poses[i].theta_rad, -kPi);
      EXPECT_LT(poses[i].theta_rad, kPi);
      for (std::size_t j = i + 1; j < poses.size(); ++j) {
        EXPECT_GE(std::hypot(poses[i].x_m - poses[j].x_m, poses[i].y_m - poses[j].y_m), params.min_spacing_m);
      }
    }
    UnicycleWorld unicycle_world(world, poses);
    unicycle_world.Step();
    EXPECT_EQ(unicycle_world.violations(), ViolationCounts{}) << "seed " << seed;
  }
}

TEST(InitialPoseGeneratorTest, TenThousandRobotsInABigArenaQuickly) {
  WorldParams world;
  world.arena = Arena{-25.0, 25.0, -20.0, 20.0};
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Pose2> poses = InitialPoseGenerator(world, InitialPoseParams{}).Generate(10000, 5);
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(poses.size(), 10000u);
  EXPECT_LT(elapsed_s, 2.0);
  UnicycleWorld unicycle_world(world, poses);
  unicycle_world.Step();
  EXPECT_EQ(unicycle_world.violations().collision_errors, 0);
}

TEST(InitialPoseGeneratorTest, ImpossibleCountsFailWithAHelpfulMessage) {
  InitialPoseParams params;
  params.max_attempts_per_robot = 50;
  // Beyond any packing: fails before sampling.
  const std::string packing = GenerateError(WorldParams{}, params, 1000);
  EXPECT_THAT(packing, HasSubstr("cannot place 1000 robots"));
  EXPECT_THAT(packing, HasSubstr("smaller min_spacing_m"));
  // Packable in principle, not by random sampling within the budget.
  const std::string sampling = GenerateError(WorldParams{}, params, 85);
  EXPECT_THAT(sampling, HasSubstr("placed only"));
  EXPECT_THAT(sampling, HasSubstr("of 85 robots"));
  EXPECT_THAT(sampling, HasSubstr("smaller min_spacing_m"));
}

TEST(InitialPoseGeneratorTest, SpacingMustClearTheCollisionGeometry) {
  InitialPoseParams params;
  params.min_spacing_m = 0.185;  // = 0.135 + 2 * 0.025: facing robots would touch
  try {
    InitialPoseGenerator generator(WorldParams{}, params);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_THAT(error.what(), HasSubstr("min_spacing_m"));
    EXPECT_THAT(error.what(), HasSubstr("0.185"));
  }
  params.min_spacing_m = 0.19;
  EXPECT_NO_THROW(InitialPoseGenerator(WorldParams{}, params).Generate(20, 3));
}

TEST(InitialPoseGeneratorTest, ZeroRobotsAndBadArguments) {
  EXPECT_TRUE(InitialPoseGenerator(WorldParams{}, InitialPoseParams{}).Generate(0, 1).empty());
  EXPECT_THROW(InitialPoseGenerator(WorldParams{}, InitialPoseParams{}).Generate(-1, 1), std::invalid_argument);
  InitialPoseParams wide_margin;
  wide_margin.wall_margin_m = 1.0;  // the arena is only 2 m tall
  EXPECT_THROW(InitialPoseGenerator(WorldParams{}, wide_margin), std::invalid_argument);
}

}  // namespace
}  // namespace dream::sim
