// DrawingIntake: what SimNode records of DREAM_DRAW_<id> and what it refuses.
#include "dream/node/drawing_intake.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dream/drawing_t.hpp"
#include "dream/lcm/channels.h"
#include "dream/world/unicycle_world.h"

namespace dream::node {
namespace {

constexpr int64_t kRun = 0x1234;

drawing_t Circle(int32_t robot, int64_t step, double x = 0.0) {
  drawing_t drawing{};
  drawing.step = step;
  drawing.run_id = kRun;
  drawing.robot_id = robot;
  drawing.agent_id = 7;
  drawing.num_shapes = 1;
  drawing.kind = {drawing_t::CIRCLE};
  drawing.rgba = {static_cast<int32_t>(0xff0000ffu)};
  drawing.width = {0.01};
  drawing.size = {0.1};
  drawing.fill = {1};
  drawing.point_count = {1};
  drawing.text_length = {0};
  drawing.num_points = 1;
  drawing.x = {x};
  drawing.y = {0.0};
  return drawing;
}

class DrawingIntakeTest : public ::testing::Test {
 protected:
  DrawingIntakeTest()
      : world_(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}), intake_(world_, kRun, bad_) {}

  Heard Take(const std::string& channel, const drawing_t& drawing) {
    std::vector<uint8_t> bytes(static_cast<size_t>(drawing.getEncodedSize()));
    drawing.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    return intake_.Take(channel, bytes.data(), static_cast<int>(bytes.size()));
  }
  std::string FirstReason(const std::string& channel) const { return bad_.first().at(channel).reason; }

  world::UnicycleWorld world_;
  lcm::BadMessageLog bad_;
  DrawingIntake intake_;
};

TEST_F(DrawingIntakeTest, ARobotsDrawingIsRecordedOnceAndItsResendIsARepeat) {
  EXPECT_EQ(Take(lcm::DrawChannel(1), Circle(1, 0)), Heard::kUsed);
  EXPECT_EQ(Take(lcm::DrawChannel(1), Circle(1, 0)), Heard::kRepeat);
  EXPECT_EQ(bad_.total(), 0);
}

TEST_F(DrawingIntakeTest, AnotherRunsOrAnotherRobotsOrAFutureStepsDrawingIsRefused) {
  drawing_t other_run = Circle(0, 0);
  other_run.run_id = kRun + 1;
  EXPECT_EQ(Take(lcm::DrawChannel(0), other_run), Heard::kRefused);
  EXPECT_EQ(Take(lcm::DrawChannel(0), Circle(1, 0)), Heard::kRefused);
  EXPECT_EQ(Take(lcm::DrawChannel(2), Circle(2, 0)), Heard::kRefused);  // the run has robots 0 and 1
  EXPECT_EQ(Take(lcm::DrawChannel(1), Circle(1, 5)), Heard::kRefused);
  EXPECT_EQ(bad_.count(lcm::DrawChannel(0)), 2);
  EXPECT_EQ(FirstReason(lcm::DrawChannel(1)), "drawing of step 5 but the world is at step 0");
}

TEST_F(DrawingIntakeTest, ADrawingThatBreaksItsTypesRulesIsRefusedNamingWhy) {
  drawing_t nan = Circle(0, 0, std::nan(""));
  EXPECT_EQ(Take(lcm::DrawChannel(0), nan), Heard::kRefused);
  EXPECT_EQ(FirstReason(lcm::DrawChannel(0)), "drawing: point 0 is not finite or past 100 m");
  drawing_t kind = Circle(1, 0);
  kind.kind = {9};
  EXPECT_EQ(Take(lcm::DrawChannel(1), kind), Heard::kRefused);
  EXPECT_EQ(FirstReason(lcm::DrawChannel(1)), "drawing: shape 0: kind 9 is none of LINE..TEXT (1..5)");
}

TEST_F(DrawingIntakeTest, BytesThatAreNoDrawingAreRefused) {
  const std::vector<uint8_t> garbage(40, 0xab);
  EXPECT_EQ(intake_.Take(lcm::DrawChannel(0), garbage.data(), static_cast<int>(garbage.size())), Heard::kRefused);
  EXPECT_EQ(FirstReason(lcm::DrawChannel(0)).rfind("cannot decode 40 bytes as drawing_t: ", 0), 0u);
}

TEST_F(DrawingIntakeTest, AFloodOfDifferentDrawingsInOneStepIsRefused) {
  for (int k = 0; k < DrawingIntake::kMaxPerRobotPerStep; ++k) {
    EXPECT_EQ(Take(lcm::DrawChannel(0), Circle(0, 0, 0.1 * k)), Heard::kUsed);
  }
  EXPECT_EQ(Take(lcm::DrawChannel(0), Circle(0, 0, 1.0)), Heard::kRefused);
  EXPECT_EQ(FirstReason(lcm::DrawChannel(0)), "more than 2 different drawings from robot 0 at step 0 (a flood)");
}

}  // namespace
}  // namespace dream::node
