// Unit tests of the Voronoi coverage experiment's pure parts, with plain
// values: polygons, cells, the coverage cost, the robot's rules, the radio
// payload and the metrics.
#include <gtest/gtest.h>

#include <cmath>

#include "dream/agents/geometry/convex_polygon.h"
#include "dream/voronoi_coverage/coverage_cost.h"
#include "dream/agents/framework/obstacle_sensor.h"
#include "dream/agents/framework/position_message.h"
#include "dream/agents/geometry/rectangle_union.h"
#include "dream/agents/geometry/voronoi_cell.h"
#include "dream/voronoi_coverage/voronoi_coverage_metrics.h"
#include "dream/voronoi_coverage/voronoi_coverage_robot.h"

namespace dream::agents {
namespace {

using Eigen::Vector2d;

// A cell with no buffers, no wall margin and a disc far larger than the
// arena: the plain Voronoi cell in the arena [-1.6, 1.6] x [-1, 1].
VoronoiCellParams PlainParams() {
  VoronoiCellParams params;
  params.disc_radius_m = 100.0;
  params.disc_sides = 64;
  params.wall_margin_m = 0.0;
  params.robot_buffer_m = 0.0;
  params.obstacle_buffer_m = 0.0;
  return params;
}

void ExpectNear(const Vector2d& actual, const Vector2d& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

TEST(ConvexPolygonTest, UnitSquareHasKnownAreaCentroidAndSecondMoment) {
  const ConvexPolygon square = ConvexPolygon::Rectangle({0.0, 0.0}, {1.0, 1.0});
  EXPECT_DOUBLE_EQ(square.Area(), 1.0);
  ExpectNear(square.Centroid(), {0.5, 0.5}, 1e-15);
  ExpectNear(square.FirstMoment(), {0.5, 0.5}, 1e-15);
  // Integral of x^2 + y^2 over the unit square: 2/3 about a corner, 1/6 about the centre.
  EXPECT_NEAR(square.SecondMoment({0.0, 0.0}), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(square.SecondMoment({0.5, 0.5}), 1.0 / 6.0, 1e-15);
  EXPECT_TRUE(ConvexPolygon::Rectangle({1.0, 0.0}, {0.0, 1.0}).empty());
}

TEST(ConvexPolygonTest, ClippingKeepsTheInsideOfTheHalfPlane) {
  const ConvexPolygon square = ConvexPolygon::Rectangle({0.0, 0.0}, {1.0, 1.0});
  const ConvexPolygon left = square.Clipped({Vector2d(1.0, 0.0), 0.25});  // x <= 0.25
  EXPECT_NEAR(left.Area(), 0.25, 1e-15);
  ExpectNear(left.Centroid(), {0.125, 0.5}, 1e-15);
  // A diagonal cut x + y <= 1 keeps the lower-left triangle.
  const ConvexPolygon triangle = square.Clipped({Vector2d(1.0, 1.0).normalized(), 1.0 / std::sqrt(2.0)});
  EXPECT_NEAR(triangle.Area(), 0.5, 1e-15);
  ExpectNear(triangle.Centroid(), {1.0 / 3.0, 1.0 / 3.0}, 1e-15);
  EXPECT_TRUE(square.Clipped({Vector2d(1.0, 0.0), -0.1}).empty());
  EXPECT_NEAR(square.Clipped({Vector2d(1.0, 0.0), 5.0}).Area(), 1.0, 1e-15);
}

TEST(ConvexPolygonTest, ClosestPointIsThePointItselfInsideAndOnTheBoundaryOutside) {
  const ConvexPolygon square = ConvexPolygon::Rectangle({0.0, 0.0}, {1.0, 1.0});
  ExpectNear(square.ClosestPoint({0.3, 0.4}), {0.3, 0.4}, 0.0);
  ExpectNear(square.ClosestPoint({2.0, 0.5}), {1.0, 0.5}, 1e-15);
  ExpectNear(square.ClosestPoint({-1.0, -2.0}), {0.0, 0.0}, 1e-15);
}

TEST(ConvexPolygonTest, RegularPolygonIsInscribed) {
  const ConvexPolygon disc = ConvexPolygon::RegularPolygon({1.0, -1.0}, 0.5, 64);
  const double expected_area = 0.5 * 64 * 0.25 * std::sin(2.0 * M_PI / 64);
  EXPECT_NEAR(disc.Area(), expected_area, 1e-14);
  EXPECT_LT(disc.Area(), M_PI * 0.25);
  ExpectNear(disc.Centroid(), {1.0, -1.0}, 1e-14);
}

TEST(VoronoiCellTest, TwoRobotsSplitTheArenaAlongTheirBisector) {
  const VoronoiCell left(PlainParams(), {-0.5, 0.2}, {{Vector2d(0.5, 0.2), 0.0}}, {});
  EXPECT_NEAR(left.polygon().Area(), 1.6 * 2.0, 1e-12);  // [-1.6, 0] x [-1, 1]
  ExpectNear(left.polygon().Centroid(), {-0.8, 0.0}, 1e-12);
  ExpectNear(left.coverage_centroid_m(), {-0.8, 0.0}, 1e-12);
  ExpectNear(left.goal_m(), {-0.8, 0.0}, 1e-12);  // no obstacle: the goal is the centroid

  // A slanted pair: every vertex of each cell is at least as close to its own robot.
  const Vector2d a(0.1, -0.3);
  const Vector2d b(0.5, 0.4);
  const VoronoiCell cell_a(PlainParams(), a, {{b, 0.0}}, {});
  const VoronoiCell cell_b(PlainParams(), b, {{a, 0.0}}, {});
  for (const Vector2d& v : cell_a.polygon().vertices()) EXPECT_LE((v - a).norm(), (v - b).norm() + 1e-12);
  for (const Vector2d& v : cell_b.polygon().vertices()) EXPECT_LE((v - b).norm(), (v - a).norm() + 1e-12);
  EXPECT_NEAR(cell_a.polygon().Area() + cell_b.polygon().Area(), 3.2 * 2.0, 1e-12);
}

TEST(VoronoiCellTest, BuffersMoveTheBisectorTowardsTheRobotAndStaleNewsMovesItFurther) {
  VoronoiCellParams params = PlainParams();
  params.robot_buffer_m = 0.1;
  const VoronoiCell cell(params, {-0.5, 0.0}, {{Vector2d(0.5, 0.0), 0.0}}, {});
  EXPECT_NEAR(cell.polygon().Area(), 1.5 * 2.0, 1e-12);  // x <= -0.1
  ExpectNear(cell.polygon().Centroid(), {-0.85, 0.0}, 1e-12);
  // The coverage share is not buffered: the cost counts every point.
  ExpectNear(cell.coverage_centroid_m(), {-0.8, 0.0}, 1e-12);
  ExpectNear(cell.goal_m(), {-0.8, 0.0}, 1e-12);

  const VoronoiCell stale(params, {-0.5, 0.0}, {{Vector2d(0.5, 0.0), 0.05}}, {});
  EXPECT_NEAR(stale.polygon().Area(), 1.45 * 2.0, 1e-12);  // x <= -0.15
}

TEST(VoronoiCellTest, AnObstaclesVirtualAgentCutsTheCellAtTheClosestPoint) {
  // Robot at the origin, obstacle closest point 0.3 m to its right: the
  // virtual agent sits at (0.6, 0) and the cell ends at x = 0.3.
  const Vector2d self(0.0, 0.0);
  const Vector2d closest(0.3, 0.0);
  const VoronoiCell cell(PlainParams(), self, {}, {closest});
  EXPECT_NEAR(cell.polygon().Area(), 1.9 * 2.0, 1e-12);
  ExpectNear(cell.polygon().Centroid(), {-0.65, 0.0}, 1e-12);
  const Vector2d virtual_agent = self + 2.0 * (closest - self);
  for (const Vector2d& v : cell.polygon().vertices()) {
    EXPECT_LE((v - self).norm(), (v - virtual_agent).norm() + 1e-12);
  }
  // With a buffer the line moves towards the robot.
  VoronoiCellParams params = PlainParams();
  params.obstacle_buffer_m = 0.12;
  const VoronoiCell buffered(params, self, {}, {closest});
  EXPECT_NEAR(buffered.polygon().Area(), 1.78 * 2.0, 1e-12);  // x <= 0.18

  // A corner seen diagonally: the whole obstacle (a box beyond the corner) is outside the cell.
  const VoronoiCell corner(PlainParams(), {0.0, 0.0}, {}, {Vector2d(0.3, 0.3)});
  for (const Vector2d& v : corner.polygon().vertices()) EXPECT_LE(v.x() + v.y(), 0.6 + 1e-12);
}

TEST(VoronoiCellTest, CoverageCentroidLeavesTheObstacleOutAndTheGoalStaysInTheCell) {
  // No neighbours, one 0.4 x 0.4 obstacle centred at (1.0, 0.0).
  const Vector2d self(0.0, 0.0);
  const ObstacleRectangle obstacle{{1.0, 0.0}, {0.4, 0.4}};
  const Vector2d closest(0.8, 0.0);
  const VoronoiCell cell(PlainParams(), self, {}, {closest}, {obstacle});
  const double arena_area = 6.4;
  const double obstacle_area = 0.16;
  EXPECT_NEAR(cell.coverage_area_m2(), arena_area - obstacle_area, 1e-12);
  // (6.4 * (0, 0) - 0.16 * (1, 0)) / 6.24
  ExpectNear(cell.coverage_centroid_m(), {-0.16 / 6.24, 0.0}, 1e-12);
  ExpectNear(cell.goal_m(), cell.coverage_centroid_m(), 1e-12);  // inside the cell

  // Behind a small obstacle the free space still counts for the robot, but
  // its goal is the nearest point of its cell, short of the obstacle.
  const VoronoiCell near(PlainParams(), {1.2, 0.5}, {}, {Vector2d(1.2, 0.2)},
                         {ObstacleRectangle{{1.2, -0.2}, {0.6, 0.8}}});
  EXPECT_LT(near.coverage_centroid_m().y(), 0.2);  // centroid pulled below the obstacle's top
  EXPECT_TRUE(near.polygon().Contains(near.goal_m(), 1e-12));
  EXPECT_GE(near.goal_m().y(), 0.2 - 1e-12);  // the goal is not behind the line
  ExpectNear(near.goal_m(), near.polygon().ClosestPoint(near.coverage_centroid_m()), 1e-15);
}

TEST(VoronoiCellTest, TheDiscLimitsTheCell) {
  VoronoiCellParams params = PlainParams();
  params.disc_radius_m = 0.5;
  const VoronoiCell cell(params, {0.0, 0.0}, {}, {});
  EXPECT_NEAR(cell.polygon().Area(), 0.5 * 64 * 0.25 * std::sin(2.0 * M_PI / 64), 1e-14);
  ExpectNear(cell.coverage_centroid_m(), {0.0, 0.0}, 1e-14);
  // Near a wall the disc is cut by the arena and the centroid moves inwards.
  const VoronoiCell corner(params, {1.4, 0.8}, {}, {});
  EXPECT_LT(corner.coverage_centroid_m().x(), 1.4);
  EXPECT_LT(corner.coverage_centroid_m().y(), 0.8);
}

TEST(VoronoiCellTest, ASqueezedRobotHasAnEmptyCell) {
  VoronoiCellParams params = PlainParams();
  params.robot_buffer_m = 0.1;
  // Neighbours 0.15 m away on both sides: x <= -0.025 and x >= 0.025.
  const VoronoiCell cell(params, {0.0, 0.0}, {{Vector2d(0.15, 0.0), 0.0}, {Vector2d(-0.15, 0.0), 0.0}}, {});
  EXPECT_TRUE(cell.empty());
  ExpectNear(cell.goal_m(), {0.0, 0.0}, 0.0);
}

TEST(VoronoiCellTest, InvalidParamsNameTheField) {
  VoronoiCellParams params;
  params.disc_radius_m = -1.0;
  std::string error;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_NE(error.find("disc_radius_m"), std::string::npos);
  EXPECT_THROW(VoronoiCell(params, {0.0, 0.0}, {}, {}), std::invalid_argument);
  // Every robot builds the disc every step: its sides are bounded.
  params = VoronoiCellParams{};
  params.disc_sides = VoronoiCellParams::kMaxDiscSides;
  EXPECT_TRUE(params.IsValid(&error)) << error;
  params.disc_sides = VoronoiCellParams::kMaxDiscSides + 1;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_EQ(error, "disc_sides must be in 8..1024, got 1025");
}

TEST(RectangleUnionTest, OverlappingRectanglesCountOnce) {
  const ConvexPolygon everything = ConvexPolygon::Rectangle({-10.0, -10.0}, {10.0, 10.0});
  // Two unit squares overlapping in a 0.5 x 1 strip, and a third inside both.
  const RectangleUnion two({{{0.0, 0.0}, {1.0, 1.0}}, {{0.5, 0.0}, {1.5, 1.0}}});
  EXPECT_NEAR(two.Area(everything), 1.5, 1e-15);
  ExpectNear(two.FirstMoment(everything), 1.5 * Vector2d(0.75, 0.5), 1e-15);
  const RectangleUnion three({{{0.0, 0.0}, {1.0, 1.0}}, {{0.5, 0.0}, {1.5, 1.0}}, {{0.6, 0.2}, {0.9, 0.8}}});
  EXPECT_NEAR(three.Area(everything), 1.5, 1e-15);
  // Clipped to a polygon: only the part inside counts.
  EXPECT_NEAR(two.Area(ConvexPolygon::Rectangle({1.0, 0.0}, {3.0, 3.0})), 0.5, 1e-15);
  EXPECT_TRUE(RectangleUnion({{{1.0, 1.0}, {0.0, 2.0}}}).empty());
}

TEST(CoverageCostTest, OneRobotAtTheCentreOfTheEmptyArena) {
  const voronoi_coverage::CoverageCost cost({-1.6, -1.0}, {1.6, 1.0});
  // Integral of x^2 + y^2 over a W x H box about its centre: W H (W^2 + H^2) / 12.
  EXPECT_NEAR(cost.Evaluate({{0.0, 0.0}}, {}), 3.2 * 2.0 * (3.2 * 3.2 + 2.0 * 2.0) / 12.0, 1e-12);
  // Two robots splitting it in halves: each half 1.6 x 2 about its centre.
  EXPECT_NEAR(cost.Evaluate({{-0.8, 0.0}, {0.8, 0.0}}, {}), 2.0 * 1.6 * 2.0 * (1.6 * 1.6 + 4.0) / 12.0, 1e-12);
  // A second robot on top of the first covers nothing new.
  EXPECT_NEAR(cost.Evaluate({{0.0, 0.0}, {0.0, 0.0}}, {}), cost.Evaluate({{0.0, 0.0}}, {}), 1e-15);
  EXPECT_DOUBLE_EQ(cost.Evaluate({}, {}), 0.0);
}

TEST(CoverageCostTest, MatchesAFineGridWithOverlappingObstaclesAndOneOutsideTheArena) {
  const Vector2d lo(-1.6, -1.0);
  const Vector2d hi(1.6, 1.0);
  const voronoi_coverage::CoverageCost cost(lo, hi);
  const std::vector<Vector2d> robots = {{-1.0, 0.5}, {0.3, -0.4}, {1.2, 0.7}, {0.0, 0.6}, {-0.9, -0.8}};
  std::vector<ObstacleView> obstacles(3);
  obstacles[0].center_m = {-0.5, 0.0};
  obstacles[0].size_m = {0.4, 0.6};
  obstacles[1].center_m = {-0.3, 0.2};  // overlaps obstacle 0
  obstacles[1].size_m = {0.4, 0.4};
  obstacles[2].center_m = {1.6, -1.0};  // three quarters outside the arena
  obstacles[2].size_m = {0.4, 0.4};
  // Midpoint rule on a 2.5 mm grid (obstacle edges lie on grid lines).
  const double h = 0.0025;
  double grid = 0.0;
  for (double x = lo.x() + h / 2; x < hi.x(); x += h) {
    for (double y = lo.y() + h / 2; y < hi.y(); y += h) {
      bool blocked = false;
      for (const ObstacleView& o : obstacles) {
        blocked = blocked ||
                  (std::abs(x - o.center_m.x()) < o.size_m.x() / 2 && std::abs(y - o.center_m.y()) < o.size_m.y() / 2);
      }
      if (blocked) continue;
      double best = INFINITY;
      for (const Vector2d& p : robots) best = std::min(best, (Vector2d(x, y) - p).squaredNorm());
      grid += best * h * h;
    }
  }
  // The midpoint rule misses h^4/6 per grid square of a quadratic (h^2/6 =
  // 1.04e-6 m^2 per m^2 of free area, ~6e-6 m^4 here) plus a little along
  // the cells' borders, where the integrand has kinks: measured 2.9e-6.
  EXPECT_NEAR(cost.Evaluate(robots, obstacles), grid, 2e-5);
}

TEST(SafeSpeedTest, AStepMayUseTheSlackButNotLeaveTheCell) {
  const std::vector<HalfPlane> wall = {{Vector2d(1.0, 0.0), 1.0}};  // x <= 1
  const double dt = 0.033;
  // Facing the wall from 0.999 m: at most 0.001 m in one step.
  EXPECT_NEAR(voronoi_coverage::VoronoiCoverageRobot::SafeSpeed(0.15, wall, {0.999, 0.0}, 0.0, dt), 0.001 / dt, 1e-12);
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::SafeSpeed(0.15, wall, {0.5, 0.0}, 0.0, dt), 0.15);
  // Backing away, or driving along the wall, is free.
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::SafeSpeed(-0.15, wall, {0.99, 0.0}, 0.0, dt), -0.15);
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::SafeSpeed(0.15, wall, {0.99, 0.0}, M_PI / 2, dt), 0.15);
  // Already beyond it: no step further out, any step back.
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::SafeSpeed(0.15, wall, {1.01, 0.0}, 0.0, dt), 0.0);
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::SafeSpeed(0.15, wall, {1.01, 0.0}, M_PI, dt), 0.15);
}

TEST(DescentSpeedTest, AStepNeverEndsFartherFromTheCentroid) {
  const double dt = 0.033;
  // Centroid 0.001 m ahead: one step may cover at most that (half the break-even 0.002 m).
  EXPECT_NEAR(voronoi_coverage::VoronoiCoverageRobot::DescentSpeed(0.15, {0.001, 0.0}, {0.0, 0.0}, 0.0, dt), 0.001 / dt,
              1e-12);
  // Centroid behind: driving forward is not allowed, backing is.
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::DescentSpeed(0.15, {-1.0, 0.0}, {0.0, 0.0}, 0.0, dt), 0.0);
  EXPECT_DOUBLE_EQ(voronoi_coverage::VoronoiCoverageRobot::DescentSpeed(-0.15, {-1.0, 0.0}, {0.0, 0.0}, 0.0, dt),
                   -0.15);
}

TEST(PositionMessageTest, RoundTripsAndRejectsMalformedPayloads) {
  const PositionMessage message{7, {0.25, -0.75}};
  const std::vector<uint8_t> payload = message.Encode();
  EXPECT_EQ(payload.size(), 20u);
  const auto decoded = PositionMessage::Decode(payload, 7);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(decoded->id, 7);
  ExpectNear(decoded->position_m, {0.25, -0.75}, 0.0);

  EXPECT_FALSE(PositionMessage::Decode(payload, 3).has_value());  // speaks for another robot
  std::vector<uint8_t> shorter(payload.begin(), payload.end() - 1);
  EXPECT_FALSE(PositionMessage::Decode(shorter, 7).has_value());
  std::vector<uint8_t> longer = payload;
  longer.push_back(0);
  EXPECT_FALSE(PositionMessage::Decode(longer, 7).has_value());
  EXPECT_FALSE(PositionMessage::Decode(PositionMessage{7, {NAN, 0.0}}.Encode(), 7).has_value());
  EXPECT_FALSE(PositionMessage::Decode({}, 7).has_value());
}

OdometryReading Odometry(int64_t step, double x, double y, double theta) {
  OdometryReading reading;
  reading.step = step;
  reading.pose = {x, y, theta};
  return reading;
}

TEST(VoronoiCoverageRobotTest, HoldsStillUntilItHeardItsNeighboursThenHeadsForItsGoal) {
  voronoi_coverage::VoronoiCoverageParams params;
  voronoi_coverage::VoronoiCoverageRobot robot(0, RobotParams{}, params);
  robot.OnOdometry(Odometry(1, 1.0, -0.5, M_PI));
  EXPECT_DOUBLE_EQ(robot.Update(1).v_mps, 0.0);
  // First radio round: nobody has spoken yet; it sends its own position.
  const auto own = robot.OnRadio({});
  ASSERT_TRUE(own.has_value());
  ASSERT_TRUE(PositionMessage::Decode(*own, 0).has_value());
  EXPECT_EQ(robot.Update(3).v_mps, 0.0);
  EXPECT_EQ(robot.Update(3).w_radps, 0.0);
  // Second round: it hears robot 1 to its right, and one malformed payload.
  robot.OnRadio({RadioMessage{1, 5, PositionMessage{1, {1.4, -0.5}}.Encode()}, RadioMessage{2, 5, {1, 2, 3}}});
  EXPECT_EQ(robot.bad_radio_messages(), 1);
  EXPECT_EQ(robot.known_neighbours(), 1u);
  const UnicycleCommand command = robot.Update(6);
  // Its goal is its cell's goal, computed from what it knows.
  const double age_buffer = params.max_speed_mps * params.step_s * 2.0;  // news from step 5, at step 6, + this step
  const VoronoiCell cell(params.cell, {1.0, -0.5}, {{Vector2d(1.4, -0.5), age_buffer}}, {});
  ExpectNear(robot.goal_m(), cell.goal_m(), 1e-12);
  EXPECT_LT(robot.goal_m().x(), 1.0);  // away from the neighbour
  // Facing -x, the goal is ahead: it drives forward.
  EXPECT_GT(command.v_mps, 0.0);
  EXPECT_FALSE(robot.done());
}

TEST(VoronoiCoverageRobotTest, StopsAtItsGoalAndReportsDoneAfterHoldingStill) {
  voronoi_coverage::VoronoiCoverageParams params;
  params.done_after_still_steps = 3;
  params.radio_rounds_before_moving = 0;
  params.cell.disc_radius_m = 0.3;
  voronoi_coverage::VoronoiCoverageRobot robot(0, RobotParams{}, params);
  // Alone in the middle of the arena: its disc's centroid is where it is.
  robot.OnOdometry(Odometry(1, 0.0, 0.0, 0.0));
  for (int step = 1; step <= 3; ++step) {
    const UnicycleCommand command = robot.Update(step);
    EXPECT_EQ(command.v_mps, 0.0);
    EXPECT_EQ(command.w_radps, 0.0);
  }
  EXPECT_TRUE(robot.done());
}

TEST(VoronoiCoverageRobotTest, OutsideItsCellItLeavesAtFullSpeed) {
  voronoi_coverage::VoronoiCoverageParams params;
  params.radio_rounds_before_moving = 0;
  voronoi_coverage::VoronoiCoverageRobot robot(0, RobotParams{}, params);
  // An obstacle's closest point 0.05 m ahead, inside the 0.12 m buffer.
  robot.OnOdometry(Odometry(1, 0.0, 0.0, M_PI));
  ObstacleReading obstacles;
  obstacles.closest_points_m = {{0.05, 0.0}};
  robot.OnObstacles(obstacles);
  const UnicycleCommand command = robot.Update(1);
  // Facing away from it (theta = pi): full speed forward (0.8 x 0.15 after dxi_to_dxu).
  EXPECT_NEAR(command.v_mps, RobotParams{}.vel_gain * params.max_speed_mps, 1e-9);
}

TEST(VoronoiCoverageParamsTest, InvalidParamsNameTheField) {
  voronoi_coverage::VoronoiCoverageParams params;
  params.max_speed_mps = 0.3;
  std::string error;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_NE(error.find("max_speed_mps"), std::string::npos);
  EXPECT_THROW(voronoi_coverage::VoronoiCoverageRobot(0, RobotParams{}, params), std::invalid_argument);
}

class ObstacleRecorder final : public Robot {
 public:
  ObstacleRecorder() : Robot(0, RobotParams{}) {}
  UnicycleCommand Update(int64_t) override { return {}; }
  using Robot::obstacles;
};

TEST(ObstacleSensorRectanglesTest, ReportsTheRectanglesOfTheObstaclesInRangeWithTheirClosestPoints) {
  WorldSnapshot world;
  world.step = 4;
  world.poses = {{0.0, 0.0, 0.0}};
  world.obstacles.push_back({0, {0.5, 0.0}, {0.2, 0.4}, {0.0, 0.0}});  // 0.4 m away
  world.obstacles.push_back({1, {0.0, 1.5}, {0.2, 0.2}, {0.0, 0.0}});  // 1.4 m away: out of range
  ObstacleRecorder robot;
  ObstacleSensor(ObstacleSensorParams{}, 1).Sense(world, robot);
  ASSERT_EQ(robot.obstacles().closest_points_m.size(), 1u);
  ASSERT_EQ(robot.obstacles().rectangles.size(), 1u);
  ExpectNear(robot.obstacles().closest_points_m[0], {0.4, 0.0}, 0.0);
  ExpectNear(robot.obstacles().rectangles[0].center_m, {0.5, 0.0}, 0.0);
  ExpectNear(robot.obstacles().rectangles[0].size_m, {0.2, 0.4}, 0.0);
  // With noise the rectangle moves with its closest point.
  ObstacleSensorParams noisy;
  noisy.noise_std = 0.01;
  ObstacleSensor(noisy, 1).Sense(world, robot);
  const Vector2d shift = robot.obstacles().closest_points_m[0] - Vector2d(0.4, 0.0);
  EXPECT_GT(shift.norm(), 0.0);
  ExpectNear(robot.obstacles().rectangles[0].center_m, Vector2d(0.5, 0.0) + shift, 1e-15);
}

WorldSnapshot Snapshot(int64_t step, std::vector<Eigen::Vector3d> poses) {
  WorldSnapshot world;
  world.step = step;
  world.poses = std::move(poses);
  return world;
}

TEST(VoronoiCoverageMetricsTest, CostSeriesRiseSettlingAndObstacleClearance) {
  voronoi_coverage::VoronoiCoverageMetricsParams params;
  params.sample_steps = 10;
  params.still_window_steps = 30;
  voronoi_coverage::VoronoiCoverageMetrics metrics(params);
  // Two robots move apart for 20 steps at 0.1 m/s, then hold still for 40.
  for (int64_t step = 0; step <= 60; ++step) {
    const double spread = 0.1 + 0.1 * 0.033 * static_cast<double>(std::min<int64_t>(step, 20));
    metrics.Observe(Snapshot(step, {{-spread, 0.0, 0.0}, {spread, 0.0, M_PI}}));
  }
  MetricsReport report;
  metrics.Write(&report);
  const auto& series = report.series.at("coverage_cost_m4");
  ASSERT_EQ(series.size(), 7u);  // steps 0, 10, ..., 60
  EXPECT_EQ(series.front().first, 0);
  EXPECT_EQ(series.back().first, 60);
  EXPECT_LT(report.values.at("coverage_cost_final_m4"), report.values.at("coverage_cost_initial_m4"));
  EXPECT_EQ(report.values.at("coverage_cost_max_rise_m4"), 0.0);
  EXPECT_EQ(report.values.at("settled_step"), 20.0);
  EXPECT_EQ(report.values.at("still_steps_at_end"), 40.0);
  EXPECT_EQ(report.values.count("min_obstacle_clearance_m"), 0u);  // no obstacles

  // Moving back together raises the cost; an obstacle close by is measured.
  voronoi_coverage::VoronoiCoverageMetrics again(params);
  WorldSnapshot world = Snapshot(0, {{-0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}});
  world.obstacles.push_back({0, {1.0, 0.0}, {0.2, 0.2}, {0.0, 0.0}});
  again.Observe(world);
  world.step = 1;
  world.poses = {{-0.1, 0.0, 0.0}, {0.85, 0.0, 0.0}};  // 0.05 m from the obstacle, facing it
  again.Observe(world);
  MetricsReport second;
  again.Write(&second);
  EXPECT_GT(second.values.at("coverage_cost_max_rise_m4"), 0.0);
  EXPECT_EQ(second.values.at("coverage_cost_max_rise_step"), 1.0);
  EXPECT_NEAR(second.values.at("min_obstacle_clearance_m"), 0.05, 1e-12);
  EXPECT_EQ(second.values.at("obstacle_contact_steps"), 1.0);
  EXPECT_EQ(second.values.at("settled_step"), -1.0);
}

}  // namespace
}  // namespace dream::agents
