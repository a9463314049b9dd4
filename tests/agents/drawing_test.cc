// agents::Drawing (what a robot draws for a step) and how a RobotAgent hands it over.
#include "dream/agents/framework/drawing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "dream/agents/framework/robot.h"
#include "dream/agents/framework/robot_agent.h"

namespace dream::agents {
namespace {

using Kind = DrawnItem::Kind;

TEST(DrawingTest, ShapesPastTheBoundAreLeftOutAndCountedByReason) {
  Drawing drawing;
  for (int k = 0; k < Drawing::kMaxShapes + 6; ++k) drawing.Line({0, 0}, {0.01 * k, 1});
  EXPECT_EQ(drawing.items().size(), static_cast<size_t>(Drawing::kMaxShapes));
  EXPECT_EQ(drawing.clipped(), 6);
  ASSERT_EQ(drawing.clip_reasons().size(), 1u);
  EXPECT_EQ(drawing.clip_reasons().begin()->first, "more than 64 shapes in one step (left out)");
}

TEST(DrawingTest, ALongPolygonIsCutAndAShortOneLeftOut) {
  Drawing drawing;
  std::vector<Eigen::Vector2d> corners;
  for (int k = 0; k < 100; ++k) corners.emplace_back(std::cos(0.06 * k), std::sin(0.06 * k));
  drawing.Polygon(corners, DrawStyle{0xff0000ffu, 0.02, true});
  drawing.Polygon({{0, 0}, {1, 1}});
  ASSERT_EQ(drawing.items().size(), 1u);
  EXPECT_EQ(drawing.items()[0].points_m.size(), static_cast<size_t>(Drawing::kMaxPolygonPoints));
  EXPECT_TRUE(drawing.items()[0].style.fill);
  EXPECT_EQ(drawing.clipped(), 36 + 1);
  EXPECT_EQ(drawing.clip_reasons().count("polygon corners past 64 (cut)"), 1u);
}

TEST(DrawingTest, TextIsCutBetweenCharactersAndMadePrintable) {
  Drawing drawing;
  std::string accents;
  for (int k = 0; k < 60; ++k) accents += "\xc3\xa9";  // 120 bytes of U+00E9
  drawing.Text({0, 0}, accents);
  drawing.Text({0, 0}, std::string("a\nb\xff", 4));
  ASSERT_EQ(drawing.items().size(), 2u);
  EXPECT_EQ(drawing.items()[0].text.size(), static_cast<size_t>(Drawing::kMaxTextBytes));
  EXPECT_EQ(drawing.items()[0].text, accents.substr(0, Drawing::kMaxTextBytes));
  EXPECT_EQ(drawing.items()[1].text, "a?b?");
  EXPECT_EQ(drawing.clipped(), 24 + 2);
}

TEST(DrawingTest, AShapeWithAPointOrSizeOutOfBoundsIsLeftOut) {
  Drawing drawing;
  drawing.Line({0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0});
  drawing.Circle({1e6, 0}, 0.1);
  drawing.Circle({0, 0}, -1);
  drawing.Arrow({0, 0}, {1, 0}, DrawStyle{0x000000ffu, std::numeric_limits<double>::infinity(), false});
  drawing.Circle({0, 0}, 0.1);
  ASSERT_EQ(drawing.items().size(), 1u);
  EXPECT_EQ(drawing.items()[0].kind, Kind::kCircle);
  EXPECT_EQ(drawing.clipped(), 4);
}

TEST(DrawingTest, OnlyCirclesAndPolygonsAreFilled) {
  Drawing drawing;
  drawing.Line({0, 0}, {1, 0}, DrawStyle{0x000000ffu, 0.01, true});
  drawing.Circle({0, 0}, 0.1, DrawStyle{0x000000ffu, 0.01, true});
  EXPECT_FALSE(drawing.items()[0].style.fill);
  EXPECT_TRUE(drawing.items()[1].style.fill);
}

// Draws a circle where it is at each update; moves at 0.1 m/s.
class CircleRobot : public Robot {
 public:
  CircleRobot() : Robot(0, RobotParams{}) {}
  UnicycleCommand Update(int64_t step) override {
    drawing().Circle({0.01 * static_cast<double>(step), 0}, 0.1);
    return UnicycleCommand{0.1, 0.0};
  }
};

TEST(DrawingTest, TheAgentHandsOverWhatTheRobotDrewWhenItsUpdateRan) {
  RobotAgentSpec spec;
  spec.robot = std::make_unique<CircleRobot>();
  spec.robot_period_steps = 2;
  RobotAgent agent(std::move(spec), 1);
  WorldSnapshot world;
  world.poses = {Eigen::Vector3d::Zero()};
  world.velocities = {Eigen::Vector2d::Zero()};
  std::vector<bool> drew;
  for (int64_t step = 1; step <= 4; ++step) {
    world.step = step;
    const RobotAgent::Output output = agent.Step(world);
    drew.push_back(output.drawing.has_value());
    if (output.drawing) {
      EXPECT_EQ(output.command.v_mps, 0.1);           // drawing never changes the command
      ASSERT_EQ(output.drawing->items().size(), 1u);  // this update's, not the ones before
      EXPECT_EQ(output.drawing->items()[0].points_m[0].x(), 0.01 * static_cast<double>(step));
    }
  }
  EXPECT_EQ(drew, (std::vector<bool>{false, true, false, true}));  // a period of 2 steps: steps 2 and 4
}

}  // namespace
}  // namespace dream::agents
