#include "dream/world/rectangle_obstacle.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace dream::world {
namespace {

RectangleObstacleSpec MovingSpec(std::vector<Eigen::Vector2d> waypoints, double speed_mps, ObstaclePathMode mode) {
  RectangleObstacleSpec spec;
  spec.id = 1;
  spec.center_m = {0.0, 0.0};
  spec.width_m = 0.2;
  spec.height_m = 0.1;
  spec.path = ObstaclePath{std::move(waypoints), speed_mps, mode};
  return spec;
}

void ExpectAt(const RectangleObstacle& obstacle, double x, double y) {
  EXPECT_NEAR(obstacle.center_m().x(), x, 1e-12);
  EXPECT_NEAR(obstacle.center_m().y(), y, 1e-12);
}

TEST(RectangleObstacleTest, StaticObstacleNeverMoves) {
  RectangleObstacleSpec spec;
  spec.center_m = {0.4, -0.3};
  spec.width_m = 0.5;
  spec.height_m = 0.25;
  RectangleObstacle obstacle(spec);
  EXPECT_TRUE(obstacle.is_static());
  for (int k = 0; k < 10; ++k) obstacle.Advance(0.033);
  ExpectAt(obstacle, 0.4, -0.3);
  EXPECT_EQ(obstacle.velocity_mps(), Eigen::Vector2d::Zero());
  EXPECT_EQ(obstacle.width_m(), 0.5);
  EXPECT_EQ(obstacle.height_m(), 0.25);
}

TEST(RectangleObstacleTest, LoopGoesRoundTheClosedPolygon) {
  // centre (0,0) -> (1,0) -> (1,1) -> back to (0,0); 0.25 m per Advance.
  RectangleObstacle obstacle(MovingSpec({Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1)}, 0.5, ObstaclePathMode::kLoop));
  EXPECT_FALSE(obstacle.is_static());
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(0.5, 0.0)));
  obstacle.Advance(0.5);
  ExpectAt(obstacle, 0.25, 0.0);
  for (int k = 0; k < 3; ++k) obstacle.Advance(0.5);
  ExpectAt(obstacle, 1.0, 0.0);  // exactly at the corner: already on the next leg
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(0.0, 0.5)));
  for (int k = 0; k < 5; ++k) obstacle.Advance(0.5);
  // 2.25 m along the perimeter 1 + 1 + sqrt(2): 0.25 m down the diagonal.
  const double diagonal = 0.25 / std::sqrt(2.0);
  ExpectAt(obstacle, 1.0 - diagonal, 1.0 - diagonal);
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(-0.5, -0.5) / std::sqrt(2.0)));
  // Carries over the closing corner onto the first leg again.
  for (int k = 0; k < 6; ++k) obstacle.Advance(0.5);  // 3.75 m total
  const double perimeter = 2.0 + std::sqrt(2.0);
  ExpectAt(obstacle, 3.75 - perimeter, 0.0);
}

TEST(RectangleObstacleTest, PingPongReversesAtTheEnds) {
  RectangleObstacle obstacle(MovingSpec({Eigen::Vector2d(1, 0)}, 1.0, ObstaclePathMode::kPingPong));
  obstacle.Advance(0.3);
  obstacle.Advance(0.3);
  obstacle.Advance(0.3);
  ExpectAt(obstacle, 0.9, 0.0);
  obstacle.Advance(0.3);  // 1.2 m: 0.2 m back from the end
  ExpectAt(obstacle, 0.8, 0.0);
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(-1.0, 0.0)));
  for (int k = 0; k < 3; ++k) obstacle.Advance(0.3);  // 2.1 m: past the start again
  ExpectAt(obstacle, 0.1, 0.0);
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(1.0, 0.0)));
}

TEST(RectangleObstacleTest, PingPongWithSeveralWaypointsRetracesThem) {
  RectangleObstacle obstacle(
      MovingSpec({Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1)}, 1.0, ObstaclePathMode::kPingPong));
  obstacle.Advance(2.5);  // out to (1,1) and 0.5 m back down
  ExpectAt(obstacle, 1.0, 0.5);
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(0.0, -1.0)));
  obstacle.Advance(1.0);
  ExpectAt(obstacle, 0.5, 0.0);
  EXPECT_TRUE(obstacle.velocity_mps().isApprox(Eigen::Vector2d(-1.0, 0.0)));
}

TEST(RectangleObstacleTest, StepsLongerThanTheWholePathWrap) {
  RectangleObstacle obstacle(MovingSpec({Eigen::Vector2d(1, 0)}, 1.0, ObstaclePathMode::kLoop));
  obstacle.Advance(10.25);  // 5 laps of 2 m plus 0.25
  ExpectAt(obstacle, 0.25, 0.0);
}

TEST(RectangleObstacleTest, RepeatedLastWaypointIsSkipped) {
  // Loop whose last waypoint repeats the centre: the zero-length leg is skipped.
  RectangleObstacle obstacle(MovingSpec({Eigen::Vector2d(0, 1), Eigen::Vector2d(0, 0)}, 1.0, ObstaclePathMode::kLoop));
  obstacle.Advance(1.5);
  ExpectAt(obstacle, 0.0, 0.5);
  obstacle.Advance(0.75);
  ExpectAt(obstacle, 0.0, 0.25);
}

TEST(RectangleObstacleTest, DiscIntersectionIncludesTouching) {
  RectangleObstacleSpec spec;
  spec.center_m = {0.0, 0.0};
  spec.width_m = 1.0;
  spec.height_m = 0.5;
  const RectangleObstacle obstacle(spec);
  EXPECT_TRUE(obstacle.IntersectsDisc(0.0, 0.0, 0.01));   // inside
  EXPECT_TRUE(obstacle.IntersectsDisc(0.75, 0.0, 0.25));  // touching the right edge
  EXPECT_FALSE(obstacle.IntersectsDisc(0.76, 0.0, 0.25));
  // Corner (0.5, 0.25); (0.375, 0.5) away, i.e. exactly 0.625 (dyadic, no rounding).
  EXPECT_TRUE(obstacle.IntersectsDisc(0.875, 0.75, 0.625));
  EXPECT_FALSE(obstacle.IntersectsDisc(0.875, 0.75, 0.62));
}

TEST(RectangleObstacleTest, InvalidSpecThrows) {
  EXPECT_THROW(RectangleObstacle(MovingSpec({}, 1.0, ObstaclePathMode::kLoop)), std::invalid_argument);
  EXPECT_THROW(RectangleObstacle(MovingSpec({Eigen::Vector2d(1, 0)}, 0.0, ObstaclePathMode::kLoop)),
               std::invalid_argument);
}

}  // namespace
}  // namespace dream::world
