// Known-answer tests for UnicycleWorld::Step against the Robotarium V2 rules.
#include "dream/world/unicycle_world.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace dream::world {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 0.033;

UnicycleWorld MakeWorld(std::vector<Pose2> poses, std::vector<RectangleObstacleSpec> obstacles = {}) {
  return UnicycleWorld(WorldParams{}, std::move(poses), obstacles);
}

// ---------------------------------------------------------------- kinematics

TEST(UnicycleWorldTest, StraightStepMovesAlongTheHeading) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}, {0.5, -0.2, kPi / 2}});
  world.SetCommand(0, {0.1, 0.0});
  world.SetCommand(1, {0.2, 0.0});
  world.Step();
  EXPECT_EQ(world.step(), 1);
  EXPECT_DOUBLE_EQ(world.poses()[0].x_m, 0.0033);  // 0.033 s * 0.1 m/s
  EXPECT_EQ(world.poses()[0].y_m, 0.0);
  EXPECT_EQ(world.poses()[0].theta_rad, 0.0);
  EXPECT_NEAR(world.poses()[1].x_m, 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(world.poses()[1].y_m, -0.2 + 0.0066);
  EXPECT_NEAR(world.poses()[1].theta_rad, kPi / 2, 1e-15);
  EXPECT_DOUBLE_EQ(world.time_s(), kDt);
}

TEST(UnicycleWorldTest, TurningStepUsesTheOldHeadingForTranslation) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}});
  world.SetCommand(0, {0.1, 1.0});
  world.Step();
  // Euler: position moves along theta = 0, then theta += 0.033.
  EXPECT_DOUBLE_EQ(world.poses()[0].x_m, 0.0033);
  EXPECT_EQ(world.poses()[0].y_m, 0.0);
  EXPECT_DOUBLE_EQ(world.poses()[0].theta_rad, 0.033);
  world.Step();  // the velocity is held
  EXPECT_DOUBLE_EQ(world.poses()[0].x_m, 0.0033 + 0.0033 * std::cos(0.033));
  EXPECT_DOUBLE_EQ(world.poses()[0].y_m, 0.0033 * std::sin(0.033));
  EXPECT_DOUBLE_EQ(world.poses()[0].theta_rad, 0.066);
}

TEST(UnicycleWorldTest, HeadingWrapsAcrossPlusAndMinusPi) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 3.1}, {0.5, 0.5, -3.1}});
  world.SetCommand(0, {0.0, 3.0});   // 3.1 + 0.099 = 3.199 -> 3.199 - 2 pi
  world.SetCommand(1, {0.0, -3.0});  // -3.199 -> 2 pi - 3.199
  world.Step();
  EXPECT_NEAR(world.poses()[0].theta_rad, 3.199 - 2 * kPi, 1e-14);
  EXPECT_NEAR(world.poses()[1].theta_rad, 2 * kPi - 3.199, 1e-14);
  EXPECT_NEAR(world.poses()[0].theta_rad, -3.0841853071795864, 1e-14);
}

TEST(UnicycleWorldTest, InitialHeadingIsNotWrappedUntilTheFirstStep) {
  // Like the official simulator: initial conditions are taken as given.
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 4.0}});
  EXPECT_EQ(world.poses()[0].theta_rad, 4.0);
  world.Step();
  EXPECT_NEAR(world.poses()[0].theta_rad, 4.0 - 2 * kPi, 1e-15);
}

// ---------------------------------------------------------------- saturation

TEST(UnicycleWorldTest, SaturatedVelocityIsStoredAndHeld) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}});
  world.SetCommand(0, {0.3, 0.0});
  EXPECT_EQ(world.velocities()[0].v_mps, 0.3);  // stored as set
  world.Step();
  EXPECT_EQ(world.velocities()[0].v_mps, 0.2);  // saturated by the step
  EXPECT_DOUBLE_EQ(world.poses()[0].x_m, 0.0066);
  EXPECT_EQ(world.violations().actuator_errors, 1);
  EXPECT_THAT(world.last_step_events().actuator_limited_robot_ids, ElementsAre(0));
  world.Step();  // held saturated velocity: no new actuator error
  EXPECT_DOUBLE_EQ(world.poses()[0].x_m, 0.0132);
  EXPECT_EQ(world.violations().actuator_errors, 1);
  EXPECT_TRUE(world.last_step_events().actuator_limited_robot_ids.empty());
}

TEST(UnicycleWorldTest, PureRotationAndMixedSaturationInTheWorld) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}, {0.5, 0.5, 0.0}});
  world.SetCommand(0, {0.0, 6.0});
  world.SetCommand(1, {0.15, 2.0});
  world.Step();
  EXPECT_EQ(world.poses()[0].x_m, 0.0);
  EXPECT_DOUBLE_EQ(world.poses()[0].theta_rad, kDt * 25.0 * 0.016 / 0.11);
  EXPECT_DOUBLE_EQ(world.poses()[1].x_m, 0.5 + kDt * 0.12);
  EXPECT_DOUBLE_EQ(world.poses()[1].theta_rad, kDt * 0.16 / 0.11);
  EXPECT_EQ(world.violations().actuator_errors, 1);  // two robots, one error
  EXPECT_THAT(world.last_step_events().actuator_limited_robot_ids, ElementsAre(0, 1));
}

// ---------------------------------------------------------------- boundary

TEST(UnicycleWorldTest, OnTheBoundaryIsInsideStrictlyOutsideIsAnError) {
  UnicycleWorld on_edge = MakeWorld({{1.6, 0.0, 0.0}, {-1.6, -1.0, 0.0}, {0.0, 1.0, 0.0}});
  on_edge.Step();
  EXPECT_EQ(on_edge.violations().boundary_errors, 0);

  UnicycleWorld outside = MakeWorld({{std::nextafter(1.6, 2.0), 0.0, 0.0}, {0.0, -1.0000001, 0.0}, {0.0, 0.0, 0.0}});
  outside.Step();
  EXPECT_EQ(outside.violations().boundary_errors, 1);  // one per step, not per robot
  EXPECT_THAT(outside.last_step_events().out_of_bounds_robot_ids, ElementsAre(0, 1));
  outside.Step();
  EXPECT_EQ(outside.violations().boundary_errors, 2);
}

TEST(UnicycleWorldTest, BoundaryIsCheckedOnThePoseBeforeTheStep) {
  // Starts inside at 1.599 and drives out: the first step validates 1.599.
  UnicycleWorld world = MakeWorld({{1.599, 0.0, 0.0}});
  world.SetCommand(0, {0.2, 0.0});
  world.Step();
  EXPECT_GT(world.poses()[0].x_m, 1.6);
  EXPECT_EQ(world.violations().boundary_errors, 0);
  world.Step();
  EXPECT_EQ(world.violations().boundary_errors, 1);
}

// ---------------------------------------------------------------- collisions

TEST(UnicycleWorldTest, CollisionExactlyAtTheDiameterCountsJustAboveDoesNot) {
  // Same heading, so both centres move by the same offset; dy = 0.135.
  UnicycleWorld at_limit = MakeWorld({{0.0, 0.0, 0.0}, {0.0, 0.135, 0.0}});
  at_limit.Step();
  EXPECT_EQ(at_limit.violations().collision_errors, 1);
  EXPECT_THAT(at_limit.last_step_events().colliding_pairs, ElementsAre(StepEvents::RobotPair{0, 1}));

  UnicycleWorld above = MakeWorld({{0.0, 0.0, 0.0}, {0.0, std::nextafter(0.135, 1.0), 0.0}});
  above.Step();
  EXPECT_EQ(above.violations().collision_errors, 0);
}

TEST(UnicycleWorldTest, ForwardOffsetMakesFacingRobotsCollideEarlier) {
  // 0.17 m apart: facing each other the offset centres are 0.12 apart,
  // facing away 0.22; without the offset neither would collide.
  UnicycleWorld facing = MakeWorld({{0.0, 0.0, 0.0}, {0.17, 0.0, kPi}});
  facing.Step();
  EXPECT_EQ(facing.violations().collision_errors, 1);

  UnicycleWorld away = MakeWorld({{0.0, 0.0, kPi}, {0.17, 0.0, 0.0}});
  away.Step();
  EXPECT_EQ(away.violations().collision_errors, 0);
}

TEST(UnicycleWorldTest, EveryCollidingPairCountsEveryStep) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}, {0.0, 0.05, 0.0}, {1.0, 0.5, 0.0}});
  world.Step();
  EXPECT_EQ(world.violations().collision_errors, 3);
  EXPECT_THAT(world.last_step_events().colliding_pairs,
              ElementsAre(StepEvents::RobotPair{0, 1}, StepEvents::RobotPair{0, 2}, StepEvents::RobotPair{1, 2}));
  world.Step();
  EXPECT_EQ(world.violations().collision_errors, 6);
}

// ---------------------------------------------------------------- obstacles

RectangleObstacleSpec Box(int id, double x, double y, double width, double height) {
  RectangleObstacleSpec spec;
  spec.id = id;
  spec.center_m = {x, y};
  spec.width_m = width;
  spec.height_m = height;
  return spec;
}

TEST(UnicycleWorldTest, ObstacleOverlapUsesTheOffsetCollisionDisc) {
  // Box edge at x = 0.9; disc radius 0.0675 around x + 0.025 (heading 0).
  const RectangleObstacleSpec box = Box(7, 1.0, 0.0, 0.2, 0.2);
  UnicycleWorld clear = MakeWorld({{0.8, 0.0, 0.0}}, {box});  // gap 0.075
  clear.Step();
  EXPECT_EQ(clear.violations().obstacle_collisions, 0);

  UnicycleWorld touching = MakeWorld({{0.81, 0.0, 0.0}}, {box});  // gap 0.065
  touching.Step();
  EXPECT_EQ(touching.violations().obstacle_collisions, 1);
  ASSERT_EQ(touching.last_step_events().obstacle_contacts.size(), 1u);
  EXPECT_EQ(touching.last_step_events().obstacle_contacts[0].robot_id, 0);
  EXPECT_EQ(touching.last_step_events().obstacle_contacts[0].obstacle_id, 7);

  UnicycleWorld facing_away = MakeWorld({{0.81, 0.0, kPi}}, {box});  // gap 0.115
  facing_away.Step();
  EXPECT_EQ(facing_away.violations().obstacle_collisions, 0);
}

TEST(UnicycleWorldTest, ObstacleOverlapsCountPerRobotObstaclePairPerStep) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}, {0.0, 0.3, 0.0}, {1.0, -0.5, 0.0}},
                                  {Box(1, 0.0, 0.0, 0.1, 0.1), Box(2, 0.05, 0.15, 0.1, 0.4)});
  world.Step();
  // Robot 0 touches both boxes, robot 1 the tall one, robot 2 none.
  EXPECT_EQ(world.violations().obstacle_collisions, 3);
  world.Step();
  EXPECT_EQ(world.violations().obstacle_collisions, 6);
  EXPECT_EQ(world.violations().collision_errors, 0);
}

TEST(UnicycleWorldTest, MovingObstacleIsCheckedWhereItIsBeforeTheStepThenAdvances) {
  // A 0.2 m box moving +x at 1 m/s (0.033 m per step) toward a robot at
  // x = 0.5 facing +x, whose disc's leftmost point is 0.5 + 0.025 - 0.0675 =
  // 0.4575: contact once the box's right edge x_c + 0.1 reaches it.
  RectangleObstacleSpec spec = Box(3, 0.0, 0.0, 0.2, 0.2);
  spec.path = ObstaclePath{{Eigen::Vector2d(1.0, 0.0)}, 1.0, ObstaclePathMode::kPingPong};
  UnicycleWorld world = MakeWorld({{0.5, 0.0, 0.0}}, {spec});
  int first_contact_step = -1;
  for (int k = 0; k < 20 && first_contact_step < 0; ++k) {
    const double box_x_before = world.obstacles()[0].center_m().x();
    world.Step();
    if (world.violations().obstacle_collisions > 0) {
      first_contact_step = k;
      EXPECT_GE(box_x_before + 0.1, 0.4575 - 1e-12);
    }
  }
  // 0.033 k + 0.1 >= 0.4575  <=>  k >= 10.83
  EXPECT_EQ(first_contact_step, 11);
  EXPECT_NEAR(world.obstacles()[0].center_m().x(), 12 * 0.033, 1e-12);
  EXPECT_DOUBLE_EQ(world.obstacles()[0].velocity_mps().x(), 1.0);
}

// ---------------------------------------------------------------- commands

TEST(UnicycleWorldTest, CommandIsHeldForFifteenStepsAndZeroedAtTheSixteenth) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}});
  EXPECT_EQ(world.command_hold_steps(), 15);
  for (int k = 0; k < 5; ++k) world.Step();
  world.SetCommand(0, {0.1, 0.0});  // set at step k = 5
  for (int k = 5; k <= 20; ++k) {   // steps 5 .. 20 still apply it
    world.Step();
    EXPECT_TRUE(world.last_step_events().timed_out_robot_ids.empty()) << "step " << k;
  }
  EXPECT_NEAR(world.poses()[0].x_m, 16 * 0.0033, 1e-15);
  EXPECT_EQ(world.velocities()[0].v_mps, 0.1);
  world.Step();  // step 21 = 5 + 16: 16 * 0.033 = 0.528 s > 0.5 s
  EXPECT_THAT(world.last_step_events().timed_out_robot_ids, ElementsAre(0));
  EXPECT_EQ(world.velocities()[0].v_mps, 0.0);
  EXPECT_NEAR(world.poses()[0].x_m, 16 * 0.0033, 1e-15);
  world.Step();  // reported once
  EXPECT_TRUE(world.last_step_events().timed_out_robot_ids.empty());
}

TEST(UnicycleWorldTest, RenewedCommandsNeverTimeOut) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}});
  for (int k = 0; k < 100; ++k) {
    if (k % 15 == 0) world.SetCommand(0, {0.1, 0.0});
    world.Step();
    ASSERT_TRUE(world.last_step_events().timed_out_robot_ids.empty()) << "step " << k;
  }
  EXPECT_NEAR(world.poses()[0].x_m, 100 * 0.0033, 1e-14);
}

TEST(UnicycleWorldTest, InfiniteTimeoutHoldsForeverLikeThePythonSimulator) {
  WorldParams params;
  params.command_timeout_s = std::numeric_limits<double>::infinity();
  UnicycleWorld world(params, {{0.0, 0.0, 0.0}});
  world.SetCommand(0, {0.1, 0.0});
  for (int k = 0; k < 1000; ++k) world.Step();
  EXPECT_EQ(world.velocities()[0].v_mps, 0.1);
}

TEST(UnicycleWorldTest, StopRobotZeroesTheHeldVelocity) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}});
  world.SetCommand(0, {0.1, 0.5});
  world.SetCommand(1, {0.1, 0.0});
  world.Step();
  world.StopRobot(0);
  const Pose2 stopped = world.poses()[0];
  for (int k = 0; k < 30; ++k) world.Step();
  EXPECT_EQ(world.poses()[0].x_m, stopped.x_m);
  EXPECT_EQ(world.poses()[0].y_m, stopped.y_m);
  EXPECT_EQ(world.velocities()[0].v_mps, 0.0);
  EXPECT_EQ(world.velocities()[0].w_radps, 0.0);
}

TEST(UnicycleWorldTest, BadCommandsAreRejected) {
  UnicycleWorld world = MakeWorld({{0.0, 0.0, 0.0}});
  EXPECT_THROW(world.SetCommand(1, {0.1, 0.0}), std::out_of_range);
  EXPECT_THROW(world.SetCommand(-1, {0.1, 0.0}), std::out_of_range);
  EXPECT_THROW(world.StopRobot(5), std::out_of_range);
  EXPECT_THROW(world.SetCommand(0, {std::nan(""), 0.0}), std::invalid_argument);
  EXPECT_THROW(world.SetCommand(0, {0.0, std::numeric_limits<double>::infinity()}), std::invalid_argument);
}

// ---------------------------------------------------------------- construction

std::string ConstructionError(const WorldParams& params, std::vector<Pose2> poses,
                              std::vector<RectangleObstacleSpec> obstacles = {}) {
  try {
    UnicycleWorld world(params, std::move(poses), obstacles);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(UnicycleWorldTest, ConstructionRejectsBadInputWithClearMessages) {
  EXPECT_THAT(ConstructionError(WorldParams{}, {{0, 0, 0}, {std::nan(""), 0, 0}}), HasSubstr("initial_poses[1]"));
  WorldParams bad_dt;
  bad_dt.time_step_s = -0.033;
  EXPECT_THAT(ConstructionError(bad_dt, {}), HasSubstr("time_step_s = -0.033"));
  EXPECT_THAT(ConstructionError(WorldParams{}, {}, {Box(4, 0, 0, 0.1, 0.1), Box(4, 1, 0, 0.1, 0.1)}),
              HasSubstr("obstacle_specs[1].id = 4"));
  EXPECT_THAT(ConstructionError(WorldParams{}, {}, {Box(4, 0, 0, -0.1, 0.1)}),
              HasSubstr("rectangle_obstacle[id=4].width_m = -0.1"));
}

TEST(UnicycleWorldTest, NoRobotLimitAndEmptyWorldsStep) {
  UnicycleWorld empty = MakeWorld({});
  empty.Step();
  EXPECT_EQ(empty.step(), 1);
  std::vector<Pose2> many;
  for (int i = 0; i < 60; ++i) many.push_back({-1.5 + 0.05 * i, 0.0, kPi / 2});
  UnicycleWorld crowded = MakeWorld(many);
  crowded.Step();
  EXPECT_EQ(crowded.num_robots(), 60);
  EXPECT_GT(crowded.violations().collision_errors, 0);
}

}  // namespace
}  // namespace dream::world
