// What controllers drew (DREAM_DRAW_<id>) in pictures: RunLog::drawings(), DrawingsShownAt and
// the arena painter's DrawingPainter, checked pixel by pixel.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dream/drawing_t.hpp"
#include "dream/lcm/channels.h"
#include "dream/render/arena_layout.h"
#include "dream/render/trajectory_picture.h"
#include "dream/run_log/run_log.h"
#include "picture_pixels.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::render {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;
using testing::kWhite;
using testing::PicturePixels;

constexpr std::array<double, 3> kGreen = {0.0, 200 / 255.0, 0.0};
constexpr std::array<double, 3> kMagenta = {200 / 255.0, 0.0, 200 / 255.0};
constexpr std::array<double, 3> kDarkBlue = {0.0, 0.0, 0.5};

struct Shape {
  int8_t kind;
  uint32_t rgba;
  double width_m;
  double size_m;
  bool fill;
  std::vector<std::array<double, 2>> points;
  std::string text;
};

drawing_t DrawingOf(int32_t robot, int64_t step, const std::vector<Shape>& shapes) {
  drawing_t d{};
  d.utime = step * 33000;
  d.step = step;
  d.robot_id = robot;
  for (const Shape& s : shapes) {
    d.kind.push_back(s.kind);
    d.rgba.push_back(static_cast<int32_t>(s.rgba));
    d.width.push_back(s.width_m);
    d.size.push_back(s.size_m);
    d.fill.push_back(s.fill ? 1 : 0);
    d.point_count.push_back(static_cast<int32_t>(s.points.size()));
    d.text_length.push_back(static_cast<int32_t>(s.text.size()));
    for (const auto& p : s.points) {
      d.x.push_back(p[0]);
      d.y.push_back(p[1]);
    }
    d.text.insert(d.text.end(), s.text.begin(), s.text.end());
  }
  d.num_shapes = static_cast<int32_t>(d.kind.size());
  d.num_points = static_cast<int32_t>(d.x.size());
  d.num_text_bytes = static_cast<int32_t>(d.text.size());
  return d;
}

const Shape kGreenDisc{drawing_t::CIRCLE, 0x00c800ffu, 0.01, 0.15, true, {{-1.2, -0.6}}, ""};
const Shape kMagentaSquare{
    drawing_t::POLYGON, 0xc800c8ffu, 0.01, 0, true, {{1.0, -0.9}, {1.4, -0.9}, {1.4, -0.5}, {1.0, -0.5}}, ""};
const Shape kBlueLine{drawing_t::LINE, 0x000080ffu, 0.04, 0, false, {{-1.4, 0.8}, {1.4, 0.8}}, ""};
const Shape kLabel{drawing_t::TEXT, 0x000000ffu, 0, 0.08, false, {{0.5, -0.8}}, "hello"};

class DrawingPainterTest : public ::testing::Test {
 protected:
  /// Two robots over 100 steps; robot 0 draws a green disc and a magenta square at step 10,
  /// robot 1 a dark blue line at step 50; with `clear_at` robot 0 draws nothing from then on.
  std::string Log(const std::string& name, int64_t clear_at = -1) const {
    SyntheticRunLog log = SyntheticRunLog::TwoRobots(dir_ / name, 100);
    log.MessageOn(lcm::DrawChannel(0), DrawingOf(0, 10, {kGreenDisc, kMagentaSquare, kLabel}));
    log.MessageOn(lcm::DrawChannel(1), DrawingOf(1, 50, {kBlueLine}));
    if (clear_at >= 0) log.MessageOn(lcm::DrawChannel(0), DrawingOf(0, clear_at, {}));
    // Not part of the run: robot 1's drawing on robot 0's channel, a robot the run does not have.
    log.MessageOn(lcm::DrawChannel(0), DrawingOf(1, 60, {kGreenDisc}));
    log.MessageOn(lcm::DrawChannel(5), DrawingOf(5, 60, {kGreenDisc}));
    return log.Write();
  }
  std::string Picture(const std::string& log, bool draw = true) const {
    const std::string png = log + ".png";
    ArenaOverlays overlays;
    overlays.draw_drawings = draw;
    TrajectoryPicture::Render(run_log::RunLog::Read(log), overlays, png, RenderFormat::kPng);
    return png;
  }
  TempFolder dir_;
  const ArenaLayout layout_{1280, 1};
};

TEST_F(DrawingPainterTest, TheLogKeepsTheRunsDrawingsByStepAndEachRobotsLatestIsShown) {
  const run_log::RunLog log = run_log::RunLog::Read(Log("cleared.lcmlog", 80));
  ASSERT_EQ(log.drawings().size(), 3u);  // the two on foreign channels left out
  EXPECT_EQ(log.drawings()[0].step, 10);
  EXPECT_EQ(log.drawings()[0].shapes.size(), 3u);
  EXPECT_EQ(log.drawings()[0].shapes[2].text, "hello");
  EXPECT_EQ(run_log::DrawingsShownAt(log.drawings(), 5).size(), 0u);
  EXPECT_EQ(run_log::DrawingsShownAt(log.drawings(), 10).size(), 1u);
  EXPECT_EQ(run_log::DrawingsShownAt(log.drawings(), 79).size(), 2u);
  const auto at_end = run_log::DrawingsShownAt(log.drawings(), 100);  // robot 0 cleared its drawing at 80
  ASSERT_EQ(at_end.size(), 1u);
  EXPECT_EQ(at_end[0]->robot_id, 1);
}

TEST_F(DrawingPainterTest, EachShapeIsDrawnWhereAndAsItWasDrawn) {
  const PicturePixels picture(Picture(Log("kept.lcmlog")));
  EXPECT_TRUE(picture.Near(layout_.px(-1.2), layout_.py(-0.6), kGreen));
  EXPECT_TRUE(picture.Near(layout_.px(-1.2 + 0.12), layout_.py(-0.6), kGreen));  // filled out to its radius
  EXPECT_TRUE(picture.Near(layout_.px(-1.2 + 0.18), layout_.py(-0.6), kWhite));
  EXPECT_TRUE(picture.Near(layout_.px(1.2), layout_.py(-0.7), kMagenta));
  EXPECT_TRUE(picture.Near(layout_.px(0.2), layout_.py(0.8), kDarkBlue, 30));
  EXPECT_TRUE(picture.Near(layout_.px(0.2), layout_.py(0.8 + 0.03), kWhite));  // 4 cm wide
  EXPECT_GT(picture.CountNear(layout_.px(0.5), layout_.py(-0.7), layout_.px(0.8), layout_.py(-0.8), {0, 0, 0}, 60), 20);
}

TEST_F(DrawingPainterTest, AClearedDrawingAndTheLayerOffLeaveNoPixels) {
  const std::string cleared = Log("cleared.lcmlog", 80);
  const PicturePixels picture(Picture(cleared));
  EXPECT_TRUE(picture.Near(layout_.px(-1.2), layout_.py(-0.6), kWhite));
  EXPECT_TRUE(picture.Near(layout_.px(0.2), layout_.py(0.8), kDarkBlue, 30));
  const PicturePixels off(Picture(Log("off.lcmlog"), /*draw=*/false));
  EXPECT_TRUE(off.Near(layout_.px(-1.2), layout_.py(-0.6), kWhite));
  EXPECT_TRUE(off.Near(layout_.px(0.2), layout_.py(0.8), kWhite));
}

}  // namespace
}  // namespace dream::render
