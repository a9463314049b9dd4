#include "dream/world/initial_pose_generator.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dream/world/start_pose_obstacle_check.h"
#include "dream/world/unicycle_world.h"
#include "obstacle_block.h"

namespace dream::world {
namespace {

using ::testing::HasSubstr;

constexpr double kPi = 3.14159265358979323846;

std::string GenerateError(const WorldParams& world, const InitialPoseParams& params, int num_robots,
                          const std::vector<RectangleObstacleSpec>& obstacles = {}) {
  try {
    InitialPoseGenerator(world, params, obstacles).Generate(num_robots, 1);
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

// Its speed (under 2 s was the target) is world_benchmark's BM_InitialPoses, not a timed test.
TEST(InitialPoseGeneratorTest, TenThousandRobotsInABigArenaStartApart) {
  WorldParams world;
  world.arena = Arena{-25.0, 25.0, -20.0, 20.0};
  const std::vector<Pose2> poses = InitialPoseGenerator(world, InitialPoseParams{}).Generate(10000, 5);
  EXPECT_EQ(poses.size(), 10000u);
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

using testing::Block;

// The world itself judges step 0: UnicycleWorld counts every obstacle
// contact and robot pair of the generated poses in its first Step().
void ExpectCleanFirstStep(const WorldParams& world, const std::vector<Pose2>& poses,
                          const std::vector<RectangleObstacleSpec>& obstacles, uint64_t seed) {
  UnicycleWorld unicycle_world(world, poses, obstacles);
  unicycle_world.Step();
  EXPECT_TRUE(unicycle_world.last_step_events().obstacle_contacts.empty()) << "seed " << seed;
  EXPECT_EQ(unicycle_world.violations(), ViolationCounts{}) << "seed " << seed;
}

TEST(InitialPoseGeneratorTest, CrowdedArenaWithObstaclesStartsClearForEverySeed) {
  const WorldParams world;
  InitialPoseParams params;
  params.min_spacing_m = 0.25;
  // A 1.6 x 0.8 m block in the middle (a fifth of the arena), a bar along the
  // top wall and a moving block whose path crosses the free space: only where
  // it is at step 0 matters.
  RectangleObstacleSpec moving = Block(2, -1.2, -0.6, 0.2, 0.2);
  moving.path = ObstaclePath{{Eigen::Vector2d(1.2, -0.6)}, 0.1, ObstaclePathMode::kPingPong};
  const std::vector<RectangleObstacleSpec> obstacles = {Block(0, 0.0, 0.0, 1.6, 0.8), Block(1, 0.0, 0.9, 3.0, 0.1),
                                                        moving};
  const InitialPoseGenerator generator(world, params, obstacles);
  for (uint64_t seed = 0; seed < 100; ++seed) {
    const std::vector<Pose2> poses = generator.Generate(30, seed);
    ASSERT_EQ(poses.size(), 30u);
    ExpectCleanFirstStep(world, poses, obstacles, seed);
  }
  // Fifty robots (the simulator's maximum) around smaller blocks.
  const std::vector<RectangleObstacleSpec> blocks = {Block(0, -0.8, 0.3, 0.5, 0.5), Block(1, 0.6, -0.3, 0.6, 0.4)};
  for (uint64_t seed = 0; seed < 50; ++seed) {
    ExpectCleanFirstStep(world, InitialPoseGenerator(world, params, blocks).Generate(50, seed), blocks, seed);
  }
}

TEST(InitialPoseGeneratorTest, ObstaclesKeepTheSeedDeterministic) {
  const std::vector<RectangleObstacleSpec> obstacles = {Block(0, 0.0, 0.0, 1.6, 0.8)};
  const InitialPoseGenerator generator(WorldParams{}, InitialPoseParams{}, obstacles);
  const std::vector<Pose2> a = generator.Generate(30, 7);
  const std::vector<Pose2> b = InitialPoseGenerator(WorldParams{}, InitialPoseParams{}, obstacles).Generate(30, 7);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x_m, b[i].x_m);
    EXPECT_EQ(a[i].y_m, b[i].y_m);
    EXPECT_EQ(a[i].theta_rad, b[i].theta_rad);
  }
  // Without obstacles the same seed places some robot on the block: the
  // obstacles changed the poses rather than being ignored.
  const StartPoseObstacleCheck check(WorldParams{}, obstacles);
  const std::vector<Pose2> free = InitialPoseGenerator(WorldParams{}, InitialPoseParams{}).Generate(30, 7);
  int touching = 0;
  for (const Pose2& pose : free) touching += check.FirstTouchedObstacle(pose) >= 0 ? 1 : 0;
  EXPECT_GT(touching, 0);
}

TEST(InitialPoseGeneratorTest, ObstacleOutOfTheWayChangesNothing) {
  // A block off in a corner outside the sampling area refuses no candidate,
  // so the poses are exactly those drawn without it.
  const std::vector<RectangleObstacleSpec> corner = {Block(0, 1.59, 0.99, 0.02, 0.02)};
  const std::vector<Pose2> with = InitialPoseGenerator(WorldParams{}, InitialPoseParams{}, corner).Generate(20, 3);
  const std::vector<Pose2> without = InitialPoseGenerator(WorldParams{}, InitialPoseParams{}).Generate(20, 3);
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t i = 0; i < with.size(); ++i) {
    EXPECT_EQ(with[i].x_m, without[i].x_m);
    EXPECT_EQ(with[i].theta_rad, without[i].theta_rad);
  }
}

TEST(InitialPoseGeneratorTest, ArenaFilledByObstaclesFailsSayingWhatToChange) {
  // Covers the whole sampling area: every candidate is refused, the attempt
  // budget ends the search and the message says why.
  const std::string covered = GenerateError(WorldParams{}, InitialPoseParams{}, 30, {Block(0, 0.0, 0.0, 3.2, 2.0)});
  EXPECT_THAT(covered, HasSubstr("placed only 0 of 30 robots"));
  EXPECT_THAT(covered, HasSubstr("after 30000 random attempts (30000 touched an obstacle, 0 were closer"));
  EXPECT_THAT(covered, HasSubstr("smaller or fewer obstacles"));
  // Room for a few robots, not for fifty: a strip 0.35 m tall at the bottom.
  const std::string crowded = GenerateError(WorldParams{}, InitialPoseParams{}, 50, {Block(0, 0.0, 0.2, 3.2, 1.6)});
  EXPECT_THAT(crowded, HasSubstr("placed only"));
  EXPECT_THAT(crowded, HasSubstr("of 50 robots"));
  EXPECT_THAT(crowded, HasSubstr("smaller or fewer obstacles, a smaller min_spacing_m or wall_margin_m"));
}

TEST(InitialPoseGeneratorTest, InvalidObstacleIsRefused) {
  EXPECT_THROW(InitialPoseGenerator(WorldParams{}, InitialPoseParams{}, {Block(0, 0.0, 0.0, 0.0, 1.0)}),
               std::invalid_argument);
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
}  // namespace dream::world
