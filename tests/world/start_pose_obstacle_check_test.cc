#include "dream/world/start_pose_obstacle_check.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "dream/world/unicycle_world.h"
#include "obstacle_block.h"

namespace dream::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

using testing::Block;

TEST(StartPoseObstacleCheckTest, TheCollisionDiscIsOffsetAlongTheHeading) {
  const WorldParams world;  // collision radius 0.0675 m, offset 0.025 m
  const StartPoseObstacleCheck check(world, {Block(0, 0.0, 0.0, 0.2, 0.2)});
  // The disc's centre is 0.025 m ahead of the pose: 0.15 m from the block's
  // right edge facing away (0.175 - 0.1 = 0.075 > 0.0675), 0.125 - 0.1 =
  // 0.025 m facing it.
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{0.15, 0.0, 0.0}), -1);
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{0.15, 0.0, kPi}), 0);
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{0.0, 0.0, 0.0}), 0);  // inside
  EXPECT_DOUBLE_EQ(check.CollisionCenterX(Pose2{0.15, 0.0, kPi}), 0.125);
  EXPECT_DOUBLE_EQ(check.collision_radius_m(), 0.0675);
}

TEST(StartPoseObstacleCheckTest, ReportsTheFirstObstacleTouchedAndNoneWithoutObstacles) {
  const StartPoseObstacleCheck check(
      WorldParams{}, {Block(7, 1.0, 0.0, 0.2, 0.2), Block(3, 0.0, 0.0, 0.4, 0.4), Block(5, 0.1, 0.0, 0.4, 0.4)});
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{0.05, 0.0, 0.0}), 1);  // an index, not the id
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{-1.0, 0.0, 0.0}), -1);
  EXPECT_FALSE(StartPoseObstacleCheck(WorldParams{}, {}).has_obstacles());
  EXPECT_EQ(StartPoseObstacleCheck(WorldParams{}, {}).FirstTouchedObstacle(Pose2{0.0, 0.0, 0.0}), -1);
}

TEST(StartPoseObstacleCheckTest, MovingObstaclesCountWhereTheyStart) {
  RectangleObstacleSpec moving = Block(0, -1.0, 0.0, 0.2, 0.2);
  moving.path = ObstaclePath{{Eigen::Vector2d(1.0, 0.0)}, 0.1, ObstaclePathMode::kPingPong};
  const StartPoseObstacleCheck check(WorldParams{}, {moving});
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{-1.0, 0.0, 0.0}), 0);
  EXPECT_EQ(check.FirstTouchedObstacle(Pose2{0.0, 0.0, 0.0}), -1);  // on its path, not at its start
}

// "Clear by this check" must mean "no contact in the world's first step",
// also on the boundary where the disc just touches (<= radius counts).
TEST(StartPoseObstacleCheckTest, AgreesWithTheWorldsFirstStepEverywhereNearTheEdges) {
  const WorldParams world;
  const std::vector<RectangleObstacleSpec> obstacles = {Block(0, 0.0, 0.0, 0.3, 0.2)};
  const StartPoseObstacleCheck check(world, obstacles);
  std::vector<Pose2> poses;
  for (int heading = 0; heading < 16; ++heading) {
    const double theta_rad = -kPi + heading * (kPi / 8.0);
    for (int k = 0; k <= 300; ++k) {
      const double d_m = 0.05 + k * 0.0005;  // from inside the block to 0.2 m beyond its edges
      poses.push_back(Pose2{0.15 + d_m - 0.05, 0.0, theta_rad});
      poses.push_back(Pose2{0.0, 0.1 + d_m - 0.05, theta_rad});
      poses.push_back(Pose2{-0.15 - d_m + 0.05, -0.1 - d_m + 0.05, theta_rad});
    }
  }
  // Exact tangency facing the block: collision centre 0.1 + 0.0675 above it.
  poses.push_back(Pose2{0.0, 0.1675 + 0.025, -kPi / 2.0});
  int touching = 0;
  for (const Pose2& pose : poses) {
    UnicycleWorld one_robot(world, {pose}, obstacles);
    one_robot.Step();
    const bool world_counts_contact = !one_robot.last_step_events().obstacle_contacts.empty();
    EXPECT_EQ(check.FirstTouchedObstacle(pose) >= 0, world_counts_contact)
        << "pose (" << pose.x_m << ", " << pose.y_m << ", " << pose.theta_rad << ")";
    touching += world_counts_contact ? 1 : 0;
  }
  EXPECT_GT(touching, 0);
  EXPECT_LT(touching, static_cast<int>(poses.size()));
}

TEST(StartPoseObstacleCheckTest, InvalidSpecsAreRefused) {
  EXPECT_THROW(StartPoseObstacleCheck(WorldParams{}, {Block(0, 0.0, 0.0, -1.0, 0.2)}), std::invalid_argument);
  WorldParams bad;
  bad.collision_diameter_m = -1.0;
  EXPECT_THROW(StartPoseObstacleCheck(bad, {}), std::invalid_argument);
}

}  // namespace
}  // namespace dream::world
