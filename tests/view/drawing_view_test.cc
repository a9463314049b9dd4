// What the controllers drew, in the view: each robot's newest DREAM_DRAW_<id> of the run drawn,
// live (BusFrameCollector, FrameJson's "drawings") and in replay (RunReplayJson's "drawings").
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dream/drawing_t.hpp"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/view/bus_frame_collector.h"
#include "dream/view/frame_json.h"
#include "dream/view/replay_json.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"
#include "two_robot_view_bus.h"

namespace dream::view {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;

// Robot `robot`'s circle at (x, 0), or with `label` a text there too.
drawing_t Drawing(int64_t run_id, int64_t step, int32_t robot, double x, const std::string& label = "") {
  drawing_t d{};
  d.run_id = run_id;
  d.step = step;
  d.utime = step * 33000;
  d.robot_id = robot;
  d.agent_id = 1;
  d.kind = {drawing_t::CIRCLE};
  d.rgba = {static_cast<int32_t>(0xff0000ffu)};
  d.width = {0.01};
  d.size = {0.1};
  d.fill = {1};
  d.point_count = {1};
  d.text_length = {0};
  d.x = {x};
  d.y = {0.0};
  if (!label.empty()) {
    d.kind.push_back(drawing_t::TEXT);
    d.rgba.push_back(0x000000ff);
    d.width.push_back(0);
    d.size.push_back(0.05);
    d.fill.push_back(0);
    d.point_count.push_back(1);
    d.text_length.push_back(static_cast<int32_t>(label.size()));
    d.x.push_back(x);
    d.y.push_back(0.2);
    d.text.assign(label.begin(), label.end());
  }
  d.num_shapes = static_cast<int32_t>(d.kind.size());
  d.num_points = static_cast<int32_t>(d.x.size());
  d.num_text_bytes = static_cast<int32_t>(d.text.size());
  return d;
}

class DrawingViewTest : public TwoRobotViewBus {
 protected:
  nlohmann::json FrameDrawings() {
    EXPECT_TRUE(collector_.TakeFrame(&frame_, &version_));
    return nlohmann::json::parse(FrameJson(frame_))["drawings"];
  }
};

TEST_F(DrawingViewTest, EachRobotsNewestDrawingOfTheRunIsInTheFrame) {
  Step(4, 0);
  Step(4, 1);
  Send("DREAM_DRAW_0", Drawing(4, 1, 0, 0.3, "hi"));
  nlohmann::json drawings = FrameDrawings();
  ASSERT_EQ(drawings.size(), 1u);
  // [step, robot, clipped, [[kind, rgba, width, size, fill, [x...], [y...], text], ...]]
  EXPECT_EQ(drawings[0][0], 1);
  EXPECT_EQ(drawings[0][1], 0);
  EXPECT_EQ(drawings[0][3][0], nlohmann::json::parse(R"([2, 4278190335, 0.01, 0.1, 1, [0.3], [0.0], ""])"));
  EXPECT_EQ(drawings[0][3][1][7], "hi");
  Step(4, 2);
  Send("DREAM_DRAW_1", Drawing(4, 2, 1, -0.4));
  Send("DREAM_DRAW_0", Drawing(4, 0, 0, 0.9));  // older than the one kept: not drawn
  drawings = FrameDrawings();
  ASSERT_EQ(drawings.size(), 2u);
  EXPECT_EQ(drawings[0][3][0][5][0], 0.3);
  EXPECT_EQ(drawings[1][3][0][5][0], -0.4);
  drawing_t empty{};
  empty.run_id = 4;
  empty.step = 2;
  Send("DREAM_DRAW_0", empty);
  drawings = FrameDrawings();
  ASSERT_EQ(drawings.size(), 1u);  // robot 0 cleared its drawing (an empty array decoded after a full one)
  EXPECT_EQ(drawings[0][1], 1);
}

TEST_F(DrawingViewTest, AnotherRunsAnotherRobotsAFutureOrABrokenDrawingIsNotDrawn) {
  Step(4, 0);
  Step(4, 1);
  ViewFrame frame;
  ASSERT_TRUE(collector_.TakeFrame(&frame, &version_));
  Send("DREAM_DRAW_0", Drawing(5, 1, 0, 0.3));  // another run
  Send("DREAM_DRAW_0", Drawing(4, 1, 1, 0.3));  // robot 1's on robot 0's channel
  Send("DREAM_DRAW_2", Drawing(4, 1, 2, 0.3));  // no robot of the run
  Send("DREAM_DRAW_1", Drawing(4, 7, 1, 0.3));  // a step to come
  drawing_t broken = Drawing(4, 1, 1, 0.3);
  broken.kind[0] = 42;
  Send("DREAM_DRAW_1", broken);
  EXPECT_FALSE(collector_.TakeFrame(&frame, &version_));
  EXPECT_EQ(collector_.bad_messages(), 1);  // the broken one
}

TEST(ReplayDrawingsTest, TheReplayListsTheRunsDrawingsByStep) {
  TempFolder folder;
  SyntheticRunLog log = SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 3);
  log.MessageOn("DREAM_DRAW_1", Drawing(0, 2, 1, 0.5, "b"));
  log.MessageOn("DREAM_DRAW_0", Drawing(0, 1, 0, -0.5));
  log.MessageOn("DREAM_DRAW_0", Drawing(7, 1, 0, -0.5));  // another run's
  const run_log::RunLog run = run_log::RunLog::Read(log.Write());
  const nlohmann::json replay = nlohmann::json::parse(RunReplayJson(run, ViewSetup()));
  ASSERT_EQ(replay["drawings"].size(), 2u);
  EXPECT_EQ(replay["drawings"][0][0], 1);
  EXPECT_EQ(replay["drawings"][0][1], 0);
  EXPECT_EQ(replay["drawings"][1][0], 2);
  EXPECT_EQ(replay["drawings"][1][3][1][7], "b");
  EXPECT_EQ(replay["drawings_cut"], false);
}

}  // namespace
}  // namespace dream::view
