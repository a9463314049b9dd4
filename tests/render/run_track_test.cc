#include "dream/render/run_track.h"

#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::sim {
namespace {

using testing::Box;
using testing::SyntheticRunLog;
using testing::TempFolder;

TEST(RunTrackTest, ReadsPosesObstaclesByStepAndRadioSends) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  // The world may publish a step's obstacles before or after its poses.
  log.Poses(0, {{0, 0, 0}, {0.3, 0.4, 0}})
      .Obstacles(0, {Box(0, 1.0, 0.0, 0.2, 0.2)})
      .Obstacles(1, {Box(0, 1.1, 0.0, 0.2, 0.2)})
      .Poses(1, {{0, 0, 0}, {0.6, 0.8, 0}})
      .Radio(1, 1)
      .Other("SOMETHING_ELSE")
      .Radio(0, 0)
      .Poses(2, {{0, 0, 0}, {0.0, 0.2, 0}});
  const RunTrack track = RunTrack::Read(log.Write());

  ASSERT_EQ(track.poses().size(), 3u);
  EXPECT_EQ(track.num_robots(), 2);
  EXPECT_EQ(track.first_step(), 0);
  EXPECT_EQ(track.last_step(), 2);
  EXPECT_NEAR(track.duration_s(), 2 * 0.033, 1e-12);
  EXPECT_DOUBLE_EQ(track.obstacles_at(0).at(0).center_x, 1.0);
  EXPECT_DOUBLE_EQ(track.obstacles_at(1).at(0).center_x, 1.1);
  EXPECT_DOUBLE_EQ(track.obstacles_at(2).at(0).center_x, 1.1);  // no message for step 2: the last one holds
  ASSERT_EQ(track.radio_sends().size(), 2u);
  EXPECT_EQ(track.radio_sends()[0].step, 0);  // sorted by step
  EXPECT_EQ(track.radio_sends()[0].sender_id, 0);
  EXPECT_EQ(track.radio_sends()[1].sender_id, 1);

  const auto closest = track.MinimumDistanceSeries();
  ASSERT_EQ(closest.size(), 3u);
  EXPECT_DOUBLE_EQ(closest[0][1], 0.5);
  EXPECT_DOUBLE_EQ(closest[1][1], 1.0);
  EXPECT_DOUBLE_EQ(closest[2][1], 0.2);
  EXPECT_DOUBLE_EQ(closest[2][0], 2.0);
}

TEST(RunTrackTest, OnlyObstaclesThatMoveHavePaths) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  for (int step = 0; step < 4; ++step) {
    log.Poses(step, {{0, 0, 0}}).Obstacles(step, {Box(0, 0.5, 0.5, 0.1, 0.1), Box(1, -0.5 + 0.1 * step, 0, 0.1, 0.1)});
  }
  const RunTrack track = RunTrack::Read(log.Write());
  EXPECT_TRUE(track.HasMovingObstacles());
  const auto paths = track.MovingObstaclePaths();
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].size(), 4u);
  EXPECT_NEAR(paths[0][3][0], -0.2, 1e-12);
  EXPECT_TRUE(track.MinimumDistanceSeries().empty());  // one robot: no pairs
}

TEST(RunTrackTest, PoseIndexAtStepFindsTheLastPoseNotAfterIt) {
  TempFolder dir;
  SyntheticRunLog log(dir / "lab.lcmlog");
  log.Poses(10, {{0, 0, 0}}).Poses(12, {{0, 0, 0}}).Poses(13, {{0, 0, 0}});  // a lab log may skip steps
  const RunTrack track = RunTrack::Read(log.Write());
  EXPECT_EQ(track.PoseIndexAtStep(0), 0u);
  EXPECT_EQ(track.PoseIndexAtStep(11), 0u);
  EXPECT_EQ(track.PoseIndexAtStep(12), 1u);
  EXPECT_EQ(track.PoseIndexAtStep(99), 2u);
  EXPECT_FALSE(track.HasMovingObstacles());
  EXPECT_TRUE(track.obstacles_at(2).empty());
}

TEST(RunTrackTest, ALogWithoutPosesIsNothingToRender) {
  TempFolder dir;
  SyntheticRunLog log(dir / "empty.lcmlog");
  log.Other("DREAM_STATUS").Radio(0, 1);
  const std::string path = log.Write();
  try {
    RunTrack::Read(path);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "no poses in " + path + ": nothing to render");
  }
}

TEST(RunTrackTest, AMissingLogIsAnErrorNamingIt) {
  TempFolder dir;
  try {
    RunTrack::Read(dir / "nope.lcmlog");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nope.lcmlog"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dream::sim
