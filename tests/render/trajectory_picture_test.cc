#include "dream/render/trajectory_picture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dream/render/arena_layout.h"
#include "picture_pixels.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::render {
namespace {

using dream::testing::Box;
using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;
using testing::kObstacleGrey;
using testing::kRobot0Blue;
using testing::kRobot1Orange;
using testing::kWhite;
using testing::PicturePixels;

constexpr double kRobotRadiusM = 0.055;

class TrajectoryPictureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    SyntheticRunLog log = SyntheticRunLog::TwoRobots(dir_ / "run.lcmlog", 100);
    log.Obstacles(100, {Box(0, 1.2, -0.6, 0.2, 0.2)});
    log_path_ = log.Write();
  }
  /// The run as a PNG with no overlays, as `dream import` draws it.
  void RenderPng(const std::string& png) const {
    TrajectoryPicture::Render(run_log::RunLog::Read(log_path_), ArenaOverlays{}, png, RenderFormat::kPng);
  }
  TempFolder dir_;
  std::string log_path_;
  const ArenaLayout layout_{1280, 1};
};

TEST_F(TrajectoryPictureTest, RobotsEndWhereTheLogSaysOnAWhiteArena) {
  const std::string png = dir_ / "trajectories.png";
  RenderPng(png);
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
  TrajectoryPicture::Render(run_log::RunLog::Read(log_path_), overlays, plain, RenderFormat::kPng);
  overlays.draw_sensor_ranges = true;
  overlays.draw_radio_links = true;
  const std::string full = dir_ / "full.png";
  TrajectoryPicture::Render(run_log::RunLog::Read(log_path_), overlays, full, RenderFormat::kPng);

  for (const std::string& png : {plain, full}) {
    const PicturePixels picture(png);
    EXPECT_TRUE(picture.Near(layout_.px(-1.2), layout_.py(0.8), kRobot0Blue, 25)) << png;  // goal crosses
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

TEST_F(TrajectoryPictureTest, TickLabelsInMetresSitOutsideTheArenaFrame) {
  const std::string png = dir_ / "trajectories.png";
  RenderPng(png);
  const PicturePixels picture(png);
  const double left = layout_.px(-1.6);
  const double bottom = layout_.py(-1.0);
  // y labels left of the frame at the grid lines (0, 1), none between them.
  EXPECT_GT(picture.CountInk(0, layout_.py(0.0) - 6, left - 2, layout_.py(0.0) + 6), 10);
  EXPECT_GT(picture.CountInk(0, layout_.py(1.0) - 6, left - 2, layout_.py(1.0) + 6), 5);
  EXPECT_EQ(picture.CountInk(0, layout_.py(0.25) - 6, left - 2, layout_.py(0.25) + 6), 0);
  // x labels under the frame at -1.5 and 1.5, none at -1.25.
  for (double x : {-1.5, 1.5}) {
    EXPECT_GT(picture.CountInk(layout_.px(x) - 14, bottom + 3, layout_.px(x) + 14, bottom + 20), 10) << x;
  }
  EXPECT_EQ(picture.CountInk(layout_.px(-1.25) - 14, bottom + 3, layout_.px(-1.25) + 14, bottom + 20), 0);
  // Small and grey: no black in the tick labels.
  EXPECT_EQ(picture.CountNear(0, layout_.py(0.0) - 6, left - 2, layout_.py(0.0) + 6, {0, 0, 0}, 60), 0);
}

TEST_F(TrajectoryPictureTest, TheLegendShowsTheMarkersTheRunUses) {
  ArenaOverlays goals;
  goals.goals_m = {{{-1.2, 0.8}}, {{0.5, -0.8}}};
  const std::string with_goals = dir_ / "goals.png";
  TrajectoryPicture::Render(run_log::RunLog::Read(log_path_), goals, with_goals, RenderFormat::kPng);
  const std::string no_goals = dir_ / "plain.png";
  TrajectoryPicture::Render(run_log::RunLog::Read(log_path_), ArenaOverlays{}, no_goals, RenderFormat::kPng);
  const std::string no_obstacles = dir_ / "empty.png";
  TrajectoryPicture::Render(run_log::RunLog::Read(SyntheticRunLog::TwoRobots(dir_ / "bare.lcmlog", 100).Write()),
                            ArenaOverlays{}, no_obstacles, RenderFormat::kPng);

  const double top = layout_.legend_center_px() - layout_.legend_row_px() / 2;
  const double bottom = layout_.legend_center_px() + layout_.legend_row_px() / 2;
  const double width = layout_.width_px();
  auto blue = [&](const PicturePixels& p) { return p.CountNear(0, top, width, bottom, kRobot0Blue, 20); };
  auto grey = [&](const PicturePixels& p) { return p.CountNear(0, top, width, bottom, kObstacleGrey, 6); };
  const PicturePixels goals_picture(with_goals);
  const PicturePixels plain_picture(no_goals);
  const PicturePixels bare_picture(no_obstacles);
  // Start (hollow) and end (filled disc, radius 0.055 m to scale) in robot 0's colour.
  const double disc_px = M_PI * std::pow(kRobotRadiusM * layout_.scale(), 2);
  EXPECT_GT(blue(plain_picture), 0.7 * disc_px);
  EXPECT_GT(blue(goals_picture), blue(plain_picture) + 20);  // and a goal cross
  EXPECT_GT(grey(plain_picture), 200);                       // the obstacle swatch
  EXPECT_LT(grey(bare_picture), 20);                         // no obstacles, no swatch (text edges only)
  EXPECT_EQ(blue(bare_picture), blue(plain_picture));
}

TEST_F(TrajectoryPictureTest, TheCaptionNamesTheRunAndItsVerdictWhenKnown) {
  const run_log::RunLog run = run_log::RunLog::Read(log_path_);
  EXPECT_EQ(TrajectoryPicture::Caption(run, ArenaOverlays{}), "2 robots, steps 0..100 (3.3 s)");
  ArenaOverlays overlays;
  overlays.run_name = "go_to_goal";
  overlays.verdict = "clean";
  EXPECT_EQ(TrajectoryPicture::Caption(run, overlays),
            "go_to_goal \xe2\x80\x94 clean (no errors or warnings) \xe2\x80\x94 2 robots, steps 0..100 (3.3 s)");
  overlays.sim_only = true;  // a clean sim_only run is not to be taken for a lab-ready one
  EXPECT_EQ(TrajectoryPicture::Caption(run, overlays),
            "go_to_goal \xe2\x80\x94 clean (no errors or warnings) \xe2\x80\x94 sim-only run (never to the lab) "
            "\xe2\x80\x94 2 robots, steps 0..100 (3.3 s)");
  overlays.sim_only = false;
  overlays.verdict = "rejected";
  EXPECT_EQ(TrajectoryPicture::Caption(run, overlays).rfind("go_to_goal \xe2\x80\x94 rejected (", 0), 0u);
  overlays.run_name.clear();
  overlays.verdict = "odd";  // an unknown verdict is shown as it is
  EXPECT_EQ(TrajectoryPicture::Caption(run, overlays), "odd \xe2\x80\x94 2 robots, steps 0..100 (3.3 s)");
  // The picture is one caption line taller than the arena, legend and all: the same size as before.
  const std::string png = dir_ / "named.png";
  TrajectoryPicture::Render(run, overlays, png, RenderFormat::kPng);
  const PicturePixels picture(png);
  EXPECT_EQ(picture.height(), layout_.height_px());
  EXPECT_GT(picture.CountInk(layout_.px(-1.6), layout_.caption_baseline_px(0) - 10, layout_.px(-1.0),
                             layout_.caption_baseline_px(0) + 2),
            20);
}

TEST_F(TrajectoryPictureTest, SvgIsAVectorPictureOfTheSameRun) {
  const std::string svg = dir_ / "trajectories.svg";
  TrajectoryPicture::Render(run_log::RunLog::Read(log_path_), ArenaOverlays{}, svg, RenderFormat::kSvg);
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
    RenderPng(png);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(png), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir_.Files(), std::vector<std::string>{"run.lcmlog"});
}

}  // namespace
}  // namespace dream::render
