#include "dream/agents/agent_host.h"

#include <gtest/gtest.h>

#include "dream/agents/controller_factory.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_poses_t.hpp"

namespace dream::agents {
namespace {

/// Counts its calls; drives forward.
class CountingController final : public Controller {
 public:
  explicit CountingController(int* calls) : calls_(calls) {}
  ControllerOutput Step(const ControllerInput& input) override {
    ++*calls_;
    return {{0.1, input.own_pose.x()}, false};
  }

 private:
  int* calls_;
};

robot_poses_t Poses(int64_t step, int num_robots) {
  robot_poses_t poses{};
  poses.step = step;
  poses.utime = step * 33000;
  poses.num_robots = num_robots;
  for (int i = 0; i < num_robots; ++i) {
    poses.x.push_back(0.1 * i);
    poses.y.push_back(0.0);
    poses.theta.push_back(0.0);
  }
  return poses;
}

class AgentHostTest : public ::testing::Test {
 protected:
  AgentHostTest() : bus_("memq://") {
    lcm::Subscribe<velocity_command_t>(
        bus_, lcm::kCommandChannelRegex,
        [this](const std::string&, const velocity_command_t& c) { commands_.push_back(c); }, bad_);
  }
  void Drain() {
    while (bus_.HandleSubscriptions(0) > 0) {
    }
  }
  lcm::LcmBus bus_;
  lcm::BadMessageLog bad_;
  std::vector<velocity_command_t> commands_;
};

TEST_F(AgentHostTest, AnswersEachStepOncePerRobotAndRepeatsForResends) {
  int calls = 0;
  std::vector<HostedRobot> robots;
  robots.push_back({1, std::make_unique<CountingController>(&calls)});
  robots.push_back({2, std::make_unique<CountingController>(&calls)});
  AgentHost host(bus_, std::move(robots), 42);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(0, 3));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(0, 3));  // the world resent step 0
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();
  EXPECT_EQ(calls, 4);  // two robots x two distinct steps
  ASSERT_EQ(commands_.size(), 6u);
  EXPECT_EQ(commands_[0].robot_id, 1);
  EXPECT_EQ(commands_[0].agent_id, 42);
  EXPECT_DOUBLE_EQ(commands_[1].w, 0.2);  // robot 2 sees its own pose (x = 0.2)
  EXPECT_EQ(commands_[2].step, 0);        // resend answered with the same command
  EXPECT_DOUBLE_EQ(commands_[2].w, commands_[0].w);
  EXPECT_EQ(commands_[5].step, 1);
}

TEST_F(AgentHostTest, MalformedPosesAndMissingRobotsAreCountedNotFatal) {
  int calls = 0;
  std::vector<HostedRobot> robots;
  robots.push_back({5, std::make_unique<CountingController>(&calls)});
  AgentHost host(bus_, std::move(robots), 1);
  const char garbage[] = "garbage";
  bus_.Publish(lcm::kPosesChannel, garbage, sizeof(garbage));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(0, 3));  // robot 5 is not in a 3-robot run
  Drain();
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(host.bad_messages().count(lcm::kPosesChannel), 2);
}

TEST(ControllerFactoryTest, UnknownKindAndBadGoalsAreClearErrors) {
  auto error_of = [](const std::string& yaml, int robots) {
    try {
      ControllerFactory(config::ConfigNode::LoadString(yaml, "c.yaml").Required("controller"), robots);
    } catch (const config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("controller: {kind: teleport}\n", 1).find("unknown controller kind 'teleport'; known kinds: "
                                                               "go_to_goal"),
            std::string::npos);
  EXPECT_NE(error_of("controller: {kind: go_to_goal, goals: [[0, 0]]}\n", 2).find("one [x, y] goal per robot (2)"),
            std::string::npos);
  EXPECT_NE(error_of("controller: {kind: go_to_goal, goals: [[0, 0]], gain: -1}\n", 1).find("gain must be > 0"),
            std::string::npos);
  EXPECT_EQ(error_of("controller: {kind: go_to_goal, goals: [[0, 0], [1, 0]]}\n", 2), "");
}

}  // namespace
}  // namespace dream::agents
