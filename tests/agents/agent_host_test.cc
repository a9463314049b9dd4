#include "dream/agents/agent_host.h"

#include <gtest/gtest.h>

#include "dream/agents/byte_reader.h"
#include "dream/agents/byte_writer.h"
#include "dream/agents/controller_factory.h"
#include "dream/agents/range_radio.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_poses_t.hpp"

namespace dream::agents {
namespace {

/// Counts its Update calls, drives at w = own x, and broadcasts its id and
/// the sum of the ids it heard.
class CountingRobot final : public Robot {
 public:
  CountingRobot(int id, int* calls) : Robot(id, RobotParams{}), calls_(calls) {}
  UnicycleCommand Update(int64_t) override {
    ++*calls_;
    return {0.1, pose().x()};
  }
  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<RadioMessage>& heard) override {
    heard_ids_sum = 0;
    for (const RadioMessage& message : heard) {
      ByteReader reader(message.payload);
      const int32_t id = reader.Int32();
      if (!reader.done()) {
        CountBadRadioMessage();
        continue;
      }
      heard_ids_sum += id;
    }
    return ByteWriter().Int32(id()).Take();
  }
  int heard_ids_sum = -1;

 private:
  int* calls_;
};

std::unique_ptr<RobotAgent> MakeAgent(int id, int* calls) {
  RobotAgentSpec spec;
  spec.robot = std::make_unique<CountingRobot>(id, calls);
  SensorSlot odometry{std::make_unique<OdometrySensor>(OdometrySensorParams{}, 1), 1};
  spec.sensors.push_back(std::move(odometry));
  spec.radio = std::make_unique<RangeRadio>(10.0);
  return std::make_unique<RobotAgent>(std::move(spec), 7);
}

robot_poses_t Poses(int64_t step, int num_robots) {
  robot_poses_t poses{};
  poses.step = step;
  poses.utime = step * 33000;
  poses.num_robots = num_robots;
  for (int i = 0; i < num_robots; ++i) {
    poses.x.push_back(0.1 * i);
    poses.y.push_back(0.0);
    poses.theta.push_back(0.0);
    poses.v.push_back(0.0);
    poses.w.push_back(0.0);
  }
  return poses;
}

class AgentHostTest : public ::testing::Test {
 protected:
  AgentHostTest() : bus_("memq://") {
    lcm::Subscribe<velocity_command_t>(
        bus_, lcm::kCommandChannelRegex,
        [this](const std::string&, const velocity_command_t& c) { commands_.push_back(c); }, bad_);
    lcm::Subscribe<radio_message_t>(
        bus_, lcm::kRadioChannelRegex,
        [this](const std::string&, const radio_message_t& m) { radio_.push_back(m); }, bad_);
  }
  void Drain() {
    while (bus_.HandleSubscriptions(0) > 0) {
    }
  }
  lcm::LcmBus bus_;
  lcm::BadMessageLog bad_;
  std::vector<velocity_command_t> commands_;
  std::vector<radio_message_t> radio_;
};

TEST_F(AgentHostTest, AnswersEachStepOncePerRobotAndRepeatsForResends) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(1, &calls));
  agents.push_back(MakeAgent(2, &calls));
  AgentHost host(bus_, std::move(agents), 42);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));  // the world resent step 1
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 3));
  Drain();
  EXPECT_EQ(calls, 4);  // two robots x two distinct steps
  ASSERT_EQ(commands_.size(), 6u);
  EXPECT_EQ(commands_[0].robot_id, 1);
  EXPECT_EQ(commands_[0].agent_id, 42);
  EXPECT_DOUBLE_EQ(commands_[1].w, 0.2);  // robot 2 sees its own pose (x = 0.2)
  EXPECT_EQ(commands_[2].step, 1);        // resend answered with the same command
  EXPECT_DOUBLE_EQ(commands_[2].w, commands_[0].w);
  EXPECT_EQ(commands_[5].step, 2);
}

TEST_F(AgentHostTest, RadioMessagesOfStepKAreHeardAtStepKPlusOne) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agents.push_back(MakeAgent(1, &calls));
  agents.push_back(MakeAgent(2, &calls));
  AgentHost host(bus_, std::move(agents), 1);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();
  ASSERT_EQ(radio_.size(), 3u);
  EXPECT_EQ(radio_[1].sender_id, 1);
  EXPECT_EQ(radio_[1].step, 1);
  // Nothing was heard at step 1: messages sent at step 1 arrive for step 2.
  const auto& robot0 = static_cast<const CountingRobot&>(host.agent(0).robot());
  EXPECT_EQ(robot0.heard_ids_sum, 0);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 3));
  Drain();
  EXPECT_EQ(robot0.heard_ids_sum, 1 + 2);
  EXPECT_EQ(static_cast<const CountingRobot&>(host.agent(2).robot()).heard_ids_sum, 0 + 1);
}

TEST_F(AgentHostTest, BadNeighbourPayloadsAreDroppedByTheRobot) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  AgentHost host(bus_, std::move(agents), 1);
  radio_message_t bad{};
  bad.step = 1;
  bad.sender_id = 5;
  bad.payload = {1, 2};  // too short for an int32
  bad.payload_size = 2;
  lcm::Publish(bus_, lcm::RadioChannel(5), bad);
  radio_message_t mismatched = bad;
  mismatched.sender_id = 6;  // not the channel's robot
  lcm::Publish(bus_, lcm::RadioChannel(5), mismatched);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 7));
  Drain();
  EXPECT_EQ(host.agent(0).robot().bad_radio_messages(), 1);
  EXPECT_EQ(host.bad_messages().count(lcm::RadioChannel(5)), 1);
}

TEST_F(AgentHostTest, MalformedPosesAndMissingRobotsAreCountedNotFatal) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(5, &calls));
  AgentHost host(bus_, std::move(agents), 1);
  const char garbage[] = "garbage";
  bus_.Publish(lcm::kPosesChannel, garbage, sizeof(garbage));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));  // robot 5 is not in a 3-robot run
  Drain();
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(host.bad_messages().count(lcm::kPosesChannel), 2);
}

TEST(ControllerFactoryTest, UnknownKindsAndBadSectionsAreClearErrors) {
  auto error_of = [](const std::string& yaml, int robots) {
    try {
      ControllerFactory(config::ConfigNode::LoadString(yaml, "c.yaml").Required("controller"), robots, 1);
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
  const std::string base = "controller:\n  kind: go_to_goal\n  goals: [[0, 0], [1, 0]]\n";
  EXPECT_NE(error_of(base + "  sensors: [{kind: sonar}]\n", 2).find("unknown sensor kind 'sonar'"), std::string::npos);
  EXPECT_NE(error_of(base + "  sensors: [{kind: odometry, period_steps: 0}]\n", 2).find("must be >= 1, got 0"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  sensors: [{kind: odometry, noise_std: -0.1}]\n", 2).find("noise_std must be >= 0"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  radio: {kind: carrier_pigeon}\n", 2).find("unknown radio kind 'carrier_pigeon'"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  radio: {kind: graph, graph: [[0, 1, 0], [1, 0, 0], [0, 0, 0]]}\n", 2)
                .find("must be 2x2"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  radio: {kind: range, loss_probability: 1.5}\n", 2).find("loss_probability must be in"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  robot: {period_steps: [1, 2, 3]}\n", 2).find("one per robot (2), got 3"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  colour: red\n", 2).find("colour: unknown key for kind go_to_goal"), std::string::npos);
}

}  // namespace
}  // namespace dream::agents
