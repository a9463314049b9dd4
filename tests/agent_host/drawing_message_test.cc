// What a C++ robot draws, on DREAM_DRAW_<id>: AgentHost sends it when it changed, just before the
// command, again with a resent step; DrawingMessageOf's drawing_t is a drawing by the world's check.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/drawing_message.h"
#include "dream/drawing_t.hpp"
#include "dream/lcm/channels.h"
#include "dream/lcm/drawing_shapes.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_poses_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::agent_host {
namespace {

constexpr int64_t kRunId = 0x7e57;

// Draws a line to (1, 0) and a label with the step, the step capped at 3: from step 3 on it draws
// the same each step.
class LabelRobot final : public agents::Robot {
 public:
  explicit LabelRobot(int id) : Robot(id, agents::RobotParams{}) {}
  agents::UnicycleCommand Update(int64_t step) override {
    drawing().Line({0, 0}, {1, 0}, agents::DrawStyle{0xff0000ffu, 0.02, false});
    drawing().Text({0, 0.1}, "k=" + std::to_string(std::min<int64_t>(step, 3)));
    return {0.1, 0.0};
  }
};

robot_poses_t Poses(int64_t step) {
  robot_poses_t poses{};
  poses.step = step;
  poses.run_id = kRunId;
  poses.utime = step * 33000;
  poses.num_robots = 1;
  poses.x = {0.0};
  poses.y = {0.0};
  poses.theta = {0.0};
  poses.v = {0.0};
  poses.w = {0.0};
  return poses;
}

TEST(DrawingMessageTest, ADrawingIsADrawingByTheWorldsCheck) {
  agents::Drawing drawing;
  drawing.Polygon({{0, 0}, {1, 0}, {1, 1}}, agents::DrawStyle{0x00ff00ffu, 0.01, true});
  drawing.Text({0.5, 0.5}, "caf\xc3\xa9");
  for (int k = 0; k < 70; ++k) drawing.Circle({0, 0}, 0.1);
  const drawing_t message = DrawingMessageOf(drawing);
  EXPECT_EQ(lcm::DrawingShapes::Problem(message), "");
  EXPECT_EQ(message.num_shapes, drawing_t::MAX_SHAPES);
  EXPECT_EQ(message.clipped, 8);
  const std::vector<lcm::DrawnShape> shapes = lcm::DrawingShapes::Of(message);
  EXPECT_EQ(shapes[0].kind, drawing_t::POLYGON);
  EXPECT_TRUE(shapes[0].fill);
  EXPECT_EQ(shapes[0].rgba, 0x00ff00ffu);
  EXPECT_EQ(shapes[1].text, "caf\xc3\xa9");
}

TEST(DrawingMessageTest, TheHostSendsADrawingBeforeItsCommandOnlyWhenItChanged) {
  lcm::LcmBus bus("memq://");
  std::vector<std::string> heard;
  std::vector<drawing_t> drawings;
  lcm::Subscription all = bus.Subscribe(
      "DREAM_(DRAW|CMD)_.*", [&](const std::string& channel, const void*, int) { heard.push_back(channel); });
  lcm::BadMessageLog bad;
  lcm::Subscription draw = lcm::Subscribe<drawing_t>(
      bus, "DREAM_DRAW_.*", [&](const std::string&, const drawing_t& d) { drawings.push_back(d); }, bad);
  std::vector<std::unique_ptr<agents::RobotAgent>> agents;
  agents::RobotAgentSpec spec;
  spec.robot = std::make_unique<LabelRobot>(0);
  agents.push_back(std::make_unique<agents::RobotAgent>(std::move(spec), 1));
  AgentHost host(bus, std::move(agents), 42);
  auto step = [&](int64_t k) {
    heard.clear();
    lcm::Publish(bus, lcm::kPosesChannel, Poses(k));
    while (bus.HandleSubscriptions(0) > 0) {
    }
    return heard;
  };
  const std::vector<std::string> both = {"DREAM_DRAW_0", "DREAM_CMD_0"};
  EXPECT_EQ(step(1), both);
  EXPECT_EQ(step(1), both);  // the world resent step 1: the same again
  EXPECT_EQ(step(2), both);
  EXPECT_EQ(step(3), both);
  EXPECT_EQ(step(4), std::vector<std::string>{"DREAM_CMD_0"});  // drew what it drew at step 3
  ASSERT_EQ(drawings.size(), 4u);
  EXPECT_EQ(drawings[0].step, 1);
  EXPECT_EQ(drawings[0].run_id, kRunId);
  EXPECT_EQ(drawings[0].agent_id, 42);
  EXPECT_EQ(std::string(drawings[3].text.begin(), drawings[3].text.end()), "k=3");
  EXPECT_EQ(bad.total(), 0);
}

}  // namespace
}  // namespace dream::agent_host
