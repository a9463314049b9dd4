#include "dream/agent_host/snapshot_from_messages.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dream::agents {
namespace {

robot_poses_t TwoRobotsAt(int64_t step) {
  robot_poses_t poses{};
  poses.step = step;
  poses.num_robots = 2;
  poses.x = {0.1, -0.4};
  poses.y = {0.2, 0.5};
  poses.theta = {0.3, -1.0};
  poses.v = {0.05, 0.0};
  poses.w = {0.5, -0.2};
  return poses;
}

rectangle_obstacle_t Obstacle(int id, double center_x) {
  rectangle_obstacle_t o{};
  o.id = id;
  o.center_x = center_x;
  o.center_y = -0.3;
  o.width = 0.2;
  o.height = 0.1;
  o.vx = 0.01;
  return o;
}

TEST(SnapshotFromMessagesTest, PosesGiveTheStepPosesAndVelocitiesAndKeepTheObstacles) {
  WorldSnapshot world;
  world.obstacles.push_back(ObstacleView{7});
  agent_host::TakePoses(TwoRobotsAt(12), &world);
  EXPECT_EQ(world.step, 12);
  ASSERT_EQ(world.num_robots(), 2);
  EXPECT_EQ(world.poses[1], Eigen::Vector3d(-0.4, 0.5, -1.0));
  EXPECT_EQ(world.velocities[0], Eigen::Vector2d(0.05, 0.5));
  ASSERT_EQ(world.obstacles.size(), 1u);
  robot_poses_t one = TwoRobotsAt(13);
  one.num_robots = 1;
  for (auto* values : {&one.x, &one.y, &one.theta, &one.v, &one.w}) values->resize(1);
  agent_host::TakePoses(one, &world);
  EXPECT_EQ(world.num_robots(), 1);
  EXPECT_EQ(world.velocities.size(), 1u);
}

TEST(SnapshotFromMessagesTest, ObstaclesReplaceTheOldOnesAndThoseWithANonFiniteValueAreLeftOut) {
  WorldSnapshot world;
  world.obstacles.push_back(ObstacleView{7});
  obstacles_t obstacles{};
  obstacles.obstacles = {Obstacle(0, 0.5), Obstacle(1, NAN), Obstacle(2, -0.5)};
  obstacles.obstacles[2].vy = INFINITY;
  obstacles.num_obstacles = 3;
  std::vector<int> non_finite;
  agent_host::TakeObstacles(obstacles, &world, &non_finite);
  ASSERT_EQ(world.obstacles.size(), 1u);
  EXPECT_EQ(world.obstacles[0].id, 0);
  EXPECT_EQ(world.obstacles[0].center_m, Eigen::Vector2d(0.5, -0.3));
  EXPECT_EQ(world.obstacles[0].size_m, Eigen::Vector2d(0.2, 0.1));
  EXPECT_EQ(world.obstacles[0].velocity_mps, Eigen::Vector2d(0.01, 0.0));
  EXPECT_EQ(non_finite, (std::vector<int>{1, 2}));
  agent_host::TakeObstacles(obstacles_t{}, &world);
  EXPECT_TRUE(world.obstacles.empty());
}

}  // namespace
}  // namespace dream::agents
