#include "dream/sim/trajectory_picture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dream/sim/arena_layout.h"
#include "picture_pixels.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::sim {
namespace {

using testing::Box;
using testing::kObstacleGrey;
using testing::kRobot0Blue;
using testing::kRobot1Orange;
using testing::kWhite;
using testing::PicturePixels;
using testing::SyntheticRunLog;
using testing::TempFolder;

constexpr double kRobotRadiusM = 0.055;

class TrajectoryPictureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    SyntheticRunLog log = SyntheticRunLog::TwoRobots(dir_ / "run.lcmlog", 100);
    log.Obstacles(100, {Box(0, 1.2, -0.6, 0.2, 0.2)});
    log_path_ = log.Write();
  }
  TempFolder dir_;
  std::string log_path_;
  const ArenaLayout layout_{1280, 1};
};

TEST_F(TrajectoryPictureTest, RobotsEndWhereTheLogSaysOnAWhiteArena) {
  const std::string png = dir_ / "trajectories.png";
  TrajectoryPicture::Render(log_path_, png);
  const PicturePixels picture(png);
  EXPECT_EQ(picture.width(), layout_.width_px());
  EXPECT_EQ(picture.height(), layout_.height_px());
  // Robot 0 ends at (1, 0.5) heading +x: its disc is blue below the centre
  // (the centre holds its id, the heading tick points right).
  const double below = 0.6 * kRobotRadiusM;
  EXPECT_TRUE(picture.Near(layout_.px(1.0), layout_.py(0.5 - below), kRobot0Blue));
  // Robot 1 stands at (0, -0.5) heading up: orange to its right.
  EXPECT_TRUE(picture.Near(layout_.px(0.6 * kRobotRadiusM), layout_.py(-0.5), kRobot1Orange));
  // Robot 0's trajectory passes through (0, 0.25).
  EXPECT_FALSE(picture.Near(layout_.px(0.0), layout_.py(0.25), kWhite, 40));
  // The obstacle, and arena nobody drove through.
  EXPECT_TRUE(picture.Near(layout_.px(1.2), layout_.py(-0.6), kObstacleGrey));
  EXPECT_TRUE(picture.Near(layout_.px(-1.2), layout_.py(-0.8), kWhite, 0));
  EXPECT_TRUE(picture.Near(layout_.px(0.8), layout_.py(0.7), kWhite, 0));
  EXPECT_EQ(dir_.Files().size(), 2u);  // the log and the picture: no temporary file left
}

TEST_F(TrajectoryPictureTest, OverlaysDrawGoalsSensorRangesAndRadioLinks) {
  ArenaOverlays overlays;
  overlays.goals_m = {{{-1.2, 0.8}}, {{0.5, -0.8}}};
  overlays.sensor_reaches = {SensorReach{0.5}};
  overlays.hears = [](int, int, const robot_poses_t&) { return true; };
  const std::string plain = dir_ / "plain.png";
  TrajectoryPicture::Render(RunTrack::Read(log_path_), overlays, plain, RenderFormat::kPng);
  overlays.draw_sensor_ranges = true;
  overlays.draw_radio_links = true;
  const std::string full = dir_ / "full.png";
  TrajectoryPicture::Render(RunTrack::Read(log_path_), overlays, full, RenderFormat::kPng);

  for (const std::string& png : {plain, full}) {
    const PicturePixels picture(png);
    EXPECT_TRUE(picture.Near(layout_.px(-1.2), layout_.py(0.8), kRobot0Blue, 25)) << png;   // goal crosses
    EXPECT_TRUE(picture.Near(layout_.px(0.5), layout_.py(-0.8), kRobot1Orange, 25)) << png;
  }
  const PicturePixels without(plain);
  const PicturePixels with(full);
  // Inside robot 1's 0.5 m sensor range, away from every line: tinted, not white.
  EXPECT_TRUE(without.Near(layout_.px(-0.3), layout_.py(-0.3), kWhite, 0));
  EXPECT_FALSE(with.Near(layout_.px(-0.3), layout_.py(-0.3), kWhite, 2));
  // A quarter of the way along the link from robot 1 (0, -0.5) to robot 0 (1, 0.5).
  EXPECT_TRUE(without.Near(layout_.px(0.25), layout_.py(-0.25), kWhite, 0));
  EXPECT_FALSE(with.Near(layout_.px(0.25), layout_.py(-0.25), kWhite, 30));
}

TEST_F(TrajectoryPictureTest, SvgIsAVectorPictureOfTheSameRun) {
  const std::string svg = dir_ / "trajectories.svg";
  TrajectoryPicture::Render(RunTrack::Read(log_path_), ArenaOverlays{}, svg, RenderFormat::kSvg);
  std::ifstream in(svg);
  std::stringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  EXPECT_EQ(content.rfind("<?xml", 0), 0u);
  EXPECT_NE(content.find("<svg"), std::string::npos);
  EXPECT_NE(content.find("</svg>"), std::string::npos);  // finished, not cut short
  EXPECT_NE(content.find("width=\"1280\""), std::string::npos);
  EXPECT_GT(content.size(), 2000u);
}

TEST_F(TrajectoryPictureTest, AFolderThatDoesNotExistIsAnErrorAndNothingIsWritten) {
  const std::string png = dir_ / "missing/trajectories.png";
  try {
    TrajectoryPicture::Render(log_path_, png);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(png), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir_.Files(), std::vector<std::string>{"run.lcmlog"});
}

}  // namespace
}  // namespace dream::sim
