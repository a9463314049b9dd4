// StepViolationLocator: one step's poses as a message carries them, checked
// with the world's rules and each violation placed (what dream render and
// dream view both mark).
#include "dream/world/step_violation_locator.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace dream::world {
namespace {

using Kind = LocatedViolation::Kind;

TEST(StepViolationLocatorTest, PlacesABoundaryACollisionAndAnObstacleAtTheirRobots) {
  StepViolationLocator locator{WorldParams{}};
  // Robot 0 and 1 0.1 m apart (too close), robot 2 outside the arena (x > 1.6), robot 3 on an obstacle.
  const std::vector<double> x = {0.0, 0.1, 1.7, -1.0}, y = {0.0, 0.0, 0.9, -0.5}, th = {0.0, 0.0, 0.0, 0.0};
  const std::vector<ObstacleState> boxes = {{7, -1.0, -0.5, 0.2, 0.2, 0.0, 0.0}};
  std::vector<LocatedViolation> found;
  ASSERT_TRUE(locator.Locate(42, 4, x, y, th, boxes, &found));
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].kind, Kind::kBoundary);
  EXPECT_EQ(found[0].robot, 2);
  EXPECT_DOUBLE_EQ(found[0].x_m, 1.7);
  EXPECT_EQ(found[1].kind, Kind::kCollision);
  EXPECT_EQ(found[1].robot, 0);
  EXPECT_EQ(found[1].other, 1);
  EXPECT_DOUBLE_EQ(found[1].x_m, 0.05);  // the middle of the pair
  EXPECT_EQ(found[2].kind, Kind::kObstacle);
  EXPECT_EQ(found[2].robot, 3);
  EXPECT_EQ(found[2].other, 7);
  for (const LocatedViolation& v : found) {
    EXPECT_EQ(v.first_step, 42);
    EXPECT_EQ(v.last_step, 42);
  }
  EXPECT_EQ(locator.last_step_events().step, 42);
  EXPECT_EQ(locator.last_poses().size(), 4u);
  // How bad each is: 0.1 m outside; collision centres (0.025 m ahead) 0.1 m apart; robot 3's
  // centre (-0.975, -0.5) is 0.075 m inside the box's nearest edge, so its 0.0675 m disc reaches
  // 0.1425 m into it.
  EXPECT_NEAR(found[0].worst_m, 0.1, 1e-12);
  EXPECT_NEAR(found[1].worst_m, 0.1, 1e-12);
  EXPECT_NEAR(found[2].worst_m, 0.0675 + 0.075, 1e-12);
}

TEST(StepViolationLocatorTest, PosesThatAreNotWholeAndFiniteFindNothing) {
  StepViolationLocator locator{WorldParams{}};
  std::vector<LocatedViolation> found;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(locator.Locate(1, 2, {0.0, 0.05}, {0.0, 0.0}, {0.0, nan}, {}, &found));
  EXPECT_FALSE(locator.Locate(1, 3, {0.0, 0.05}, {0.0, 0.0}, {0.0, 0.0}, {}, &found));  // a count that lies
  EXPECT_FALSE(locator.Locate(1, 0, {}, {}, {}, {}, &found));
  EXPECT_TRUE(found.empty());
}

TEST(StepViolationLocatorTest, ARobotCountThatChangesRemakesTheCheckerAndAnObstacleNotFiniteIsLeftOut) {
  StepViolationLocator locator{WorldParams{}};
  std::vector<LocatedViolation> found;
  ASSERT_TRUE(locator.Locate(1, 2, {0.0, 0.5}, {0.0, 0.0}, {0.0, 0.0}, {}, &found));
  EXPECT_TRUE(found.empty());
  const double inf = std::numeric_limits<double>::infinity();
  ASSERT_TRUE(locator.Locate(2, 3, {0.0, 0.5, 0.55}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0},
                             {{1, 0.0, 0.0, inf, 0.2, 0.0, 0.0}}, &found));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, Kind::kCollision);
  EXPECT_EQ(found[0].robot, 1);
  EXPECT_EQ(found[0].other, 2);
}

}  // namespace
}  // namespace dream::world
