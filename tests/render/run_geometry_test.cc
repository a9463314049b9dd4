#include "dream/render/run_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::render {
namespace {

using dream::testing::Box;
using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;
using run_log::RunLog;

TEST(RunGeometryTest, DurationPathsAndClosestApproachPerStep) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Poses(0, {{0, 0, 0}, {0.3, 0.4, 0}}).Poses(1, {{0, 0, 0}, {0.6, 0.8, 0}}).Poses(2, {{0, 0, 0}, {0.0, 0.2, 0}});
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_NEAR(DurationS(run), 2 * 0.033, 1e-12);
  const auto path = RobotPath(run, 1);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_DOUBLE_EQ(path[1][0], 0.6);
  EXPECT_DOUBLE_EQ(path[1][1], 0.8);
  ASSERT_EQ(RobotPath(run, 1, 1, 1).size(), 1u);  // a trail: poses 1..1
  EXPECT_TRUE(RobotPath(run, 2).empty());         // no such robot

  const auto closest = MinimumDistanceSeries(run);
  ASSERT_EQ(closest.size(), 3u);
  EXPECT_DOUBLE_EQ(closest[0][1], 0.5);
  EXPECT_DOUBLE_EQ(closest[1][1], 1.0);
  EXPECT_DOUBLE_EQ(closest[2][1], 0.2);
  EXPECT_DOUBLE_EQ(closest[2][0], 2.0);
}

TEST(RunGeometryTest, OnlyObstaclesThatMoveHavePaths) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  for (int step = 0; step < 4; ++step) {
    log.Poses(step, {{0, 0, 0}}).Obstacles(step, {Box(0, 0.5, 0.5, 0.1, 0.1), Box(1, -0.5 + 0.1 * step, 0, 0.1, 0.1)});
  }
  const RunLog run = RunLog::Read(log.Write());
  const auto paths = MovingObstaclePaths(run);
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].size(), 4u);
  EXPECT_NEAR(paths[0][3][0], -0.2, 1e-12);
  EXPECT_TRUE(MinimumDistanceSeries(run).empty());  // one robot: no pairs
}

TEST(RunGeometryTest, ALogWithoutPosesIsNothingToRender) {
  TempFolder dir;
  SyntheticRunLog log(dir / "empty.lcmlog");
  log.Other("DREAM_STATUS").Radio(0, 1);
  const RunLog run = RunLog::Read(log.Write());
  try {
    Drawable(run);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "no poses in " + run.path() + ": nothing to render");
  }
  EXPECT_TRUE(RobotPath(run, 0).empty());
}

}  // namespace
}  // namespace dream::render
