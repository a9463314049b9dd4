#include "dream/agent_host/agent_host.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <limits>
#include <set>
#include <sstream>

#include "dream/agents/framework/byte_reader.h"
#include "dream/agents/framework/byte_writer.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agents/framework/graph_radio.h"
#include "dream/agents/framework/range_radio.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/message_limits.h"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"

namespace dream::agents {
namespace {

/// Counts its Update calls, drives at w = own x, broadcasts its id and keeps
/// the ids it heard; a payload that is not one int32 is counted as bad (with
/// its sender unless name_bad_senders is false).
class CountingRobot final : public Robot {
 public:
  CountingRobot(int id, int* calls) : Robot(id, RobotParams{}), calls_(calls) {}
  UnicycleCommand Update(int64_t) override {
    ++*calls_;
    return {v_mps, pose().x()};
  }
  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<RadioMessage>& heard) override {
    heard_ids.clear();
    for (const RadioMessage& message : heard) {
      ByteReader reader(message.payload);
      const int32_t id = reader.Int32();
      if (!reader.done()) {
        if (name_bad_senders) {
          CountBadRadioMessage(message);
        } else {
          CountBadRadioMessage();
        }
        continue;
      }
      heard_ids.push_back(id);
    }
    std::vector<uint8_t> payload = ByteWriter().Int32(id()).Take();
    payload.resize(payload.size() + extra_payload_bytes);
    return payload;
  }
  std::vector<int> heard_ids;
  bool name_bad_senders = true;
  size_t extra_payload_bytes = 0;  // zeros after its id
  double v_mps = 0.1;

 private:
  int* calls_;
};

std::unique_ptr<RobotAgent> MakeAgent(int id, int* calls, std::unique_ptr<Radio> radio = nullptr,
                                      bool name_bad_senders = true, size_t extra_payload_bytes = 0,
                                      double v_mps = 0.1) {
  RobotAgentSpec spec;
  auto robot = std::make_unique<CountingRobot>(id, calls);
  robot->name_bad_senders = name_bad_senders;
  robot->extra_payload_bytes = extra_payload_bytes;
  robot->v_mps = v_mps;
  spec.robot = std::move(robot);
  SensorSlot odometry{std::make_unique<OdometrySensor>(OdometrySensorParams{}, 1), 1};
  spec.sensors.push_back(std::move(odometry));
  spec.radio = radio ? std::move(radio) : std::make_unique<RangeRadio>(10.0);
  return std::make_unique<RobotAgent>(std::move(spec), 7);
}

const CountingRobot& Counting(const agent_host::AgentHost& host, size_t i) {
  return static_cast<const CountingRobot&>(host.agent(i).robot());
}

constexpr int64_t kRunId = 0x7e57;

robot_poses_t Poses(int64_t step, int num_robots, int64_t run_id = kRunId) {
  robot_poses_t poses{};
  poses.step = step;
  poses.run_id = run_id;
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
    subscriptions_.push_back(lcm::Subscribe<velocity_command_t>(
        bus_, lcm::kCommandChannelRegex,
        [this](const std::string&, const velocity_command_t& c) { commands_.push_back(c); }, bad_));
    subscriptions_.push_back(lcm::Subscribe<radio_message_t>(
        bus_, lcm::kRadioChannelRegex, [this](const std::string&, const radio_message_t& m) { radio_.push_back(m); },
        bad_));
  }
  void Drain() {
    while (bus_.HandleSubscriptions(0) > 0) {
    }
  }
  // The robots the host gives up, on DREAM_FAULT_<id>, into faults_.
  void HearFaults() {
    subscriptions_.push_back(lcm::Subscribe<robot_fault_t>(
        bus_, lcm::kFaultChannelRegex, [this](const std::string&, const robot_fault_t& f) { faults_.push_back(f); },
        bad_));
  }
  lcm::LcmBus bus_;
  lcm::BadMessageLog bad_;
  std::vector<velocity_command_t> commands_;
  std::vector<radio_message_t> radio_;
  std::vector<robot_fault_t> faults_;
  std::vector<lcm::Subscription> subscriptions_;  // last: ends before what the handlers use
};

TEST_F(AgentHostTest, AnswersEachStepOncePerRobotAndRepeatsForResends) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(1, &calls));
  agents.push_back(MakeAgent(2, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 42);
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
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();
  ASSERT_EQ(radio_.size(), 3u);
  EXPECT_EQ(radio_[1].sender_id, 1);
  EXPECT_EQ(radio_[1].step, 1);
  // Nothing was heard at step 1: messages sent at step 1 arrive for step 2.
  EXPECT_TRUE(Counting(host, 0).heard_ids.empty());
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 3));
  Drain();
  EXPECT_EQ(Counting(host, 0).heard_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(Counting(host, 2).heard_ids, (std::vector<int>{0, 1}));
}

// Every message reaches every host on the bus; each receiving robot's radio
// decides, from the world's poses, whom it hears.
// Issue 23: a payload over the limit was sent, every receiver dropped it, and
// the run was clean. The host gives the robot up instead, saying why.
TEST_F(AgentHostTest, ARadioPayloadOverTheLimitIsTheControllersFaultNotAMessage) {
  HearFaults();
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agents.push_back(MakeAgent(1, &calls, nullptr, true, lcm::MessageLimits::kRadioPayloadBytes - 3));  // 65537 bytes
  agent_host::AgentHost host(bus_, std::move(agents), 5);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 2));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 2));  // a resend: no second fault
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 2));
  Drain();
  ASSERT_EQ(faults_.size(), 1u);
  EXPECT_EQ(faults_[0].robot_id, 1);
  EXPECT_EQ(faults_[0].step, 1);
  EXPECT_EQ(faults_[0].run_id, kRunId);
  EXPECT_EQ(faults_[0].agent_id, 5);
  EXPECT_EQ(faults_[0].detail,
            "robot 1: OnRadio returned a payload of 65537 bytes, over the limit of 65536 bytes (every receiver "
            "would drop it)");
  for (const radio_message_t& radio : radio_) EXPECT_EQ(radio.sender_id, 0);
  for (const velocity_command_t& command : commands_) EXPECT_EQ(command.robot_id, 0);
  EXPECT_EQ(commands_.size(), 3u);  // robot 0 goes on
  EXPECT_EQ(bad_.total(), 0);
}

// A command that is not a number was sent, the world refused it at every step
// and the robot held still with nothing but dropped messages to say why.
TEST_F(AgentHostTest, ANonFiniteCommandIsTheControllersFaultNotAMessage) {
  HearFaults();
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agents.push_back(MakeAgent(1, &calls, nullptr, true, 0, std::numeric_limits<double>::quiet_NaN()));
  agent_host::AgentHost host(bus_, std::move(agents), 5);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 2));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 2));
  Drain();
  ASSERT_EQ(faults_.size(), 1u);
  EXPECT_EQ(faults_[0].robot_id, 1);
  EXPECT_EQ(faults_[0].step, 1);
  EXPECT_EQ(faults_[0].detail,
            "robot 1: Update returned a command that is not finite (v=nan m/s, w=0.100000 rad/s; the world would "
            "refuse it)");
  ASSERT_EQ(commands_.size(), 2u);  // robot 0 goes on
  for (const velocity_command_t& command : commands_) EXPECT_EQ(command.robot_id, 0);
  EXPECT_EQ(bad_.total(), 0);
}

TEST_F(AgentHostTest, RangeRadioHearsOnlyRobotsInRangeOfTheReceiver) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  for (int id = 0; id < 3; ++id) agents.push_back(MakeAgent(id, &calls, std::make_unique<RangeRadio>(0.15)));
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  // Poses() puts robot i at x = 0.1 i: 0 and 2 are 0.2 m apart, beyond 0.15 m.
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();
  ASSERT_EQ(radio_.size(), 3u);  // everyone spoke, on the bus for all
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 3));
  Drain();
  EXPECT_EQ(Counting(host, 0).heard_ids, (std::vector<int>{1}));
  EXPECT_EQ(Counting(host, 1).heard_ids, (std::vector<int>{0, 2}));
  EXPECT_EQ(Counting(host, 2).heard_ids, (std::vector<int>{1}));
}

TEST_F(AgentHostTest, GraphRadioDoesNotHearUnlinkedSenders) {
  // Row i lists whom robot i hears: 0 hears 1 and 2, 1 hears 0, 2 hears nobody
  // (though 0 hears 2: links are one-way unless the matrix says both).
  Eigen::MatrixXd adjacency(3, 3);
  adjacency << 0, 1, 1,  //
      1, 0, 0,           //
      0, 0, 0;
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  for (int id = 0; id < 3; ++id) {
    auto radio = std::make_unique<GraphRadio>(CommunicationGraph(adjacency, 3, false, false));
    agents.push_back(MakeAgent(id, &calls, std::move(radio)));
  }
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();  // everyone speaks at step 1...
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 3));
  Drain();  // ... and hears at step 2
  EXPECT_EQ(Counting(host, 0).heard_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(Counting(host, 1).heard_ids, (std::vector<int>{0}));
  EXPECT_TRUE(Counting(host, 2).heard_ids.empty());
}

/// A step-1 radio message from `sender_id` whose payload no robot can decode
/// (too short for an int32).
radio_message_t UndecodableRadioMessage(int sender_id) {
  radio_message_t message{};
  message.step = 1;
  message.run_id = kRunId;
  message.sender_id = sender_id;
  message.payload = {1, 2};
  message.payload_size = 2;
  return message;
}

TEST_F(AgentHostTest, BadNeighbourPayloadsAreDroppedByTheRobot) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  const radio_message_t bad = UndecodableRadioMessage(5);
  lcm::Publish(bus_, lcm::RadioChannel(5), bad);
  radio_message_t mismatched = bad;
  mismatched.sender_id = 6;  // not the channel's robot
  lcm::Publish(bus_, lcm::RadioChannel(5), mismatched);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 7));
  Drain();
  EXPECT_EQ(host.agent(0).robot().bad_radio_messages(), 1);
  EXPECT_EQ(host.bad_messages().count(lcm::RadioChannel(5)), 1);
}

TEST_F(AgentHostTest, RadioFromSendersOutsideTheRunIsCountedNotKept) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  for (int sender : {2, 3, 1000}) {
    radio_message_t message = UndecodableRadioMessage(sender);
    message.agent_id = 77;
    lcm::Publish(bus_, lcm::RadioChannel(sender), message);
  }
  Drain();
  EXPECT_EQ(host.bad_messages().count(lcm::RadioChannel(2)), 0);  // a robot of the run
  EXPECT_EQ(host.bad_messages().count(lcm::RadioChannel(3)), 1);
  EXPECT_EQ(host.bad_messages().count(lcm::RadioChannel(1000)), 1);
  EXPECT_EQ(host.bad_messages().senders().at(lcm::RadioChannel(1000)), std::set<int64_t>{77});
}

TEST_F(AgentHostTest, ForgedCountsOnTheWorldsChannelsAreCountedAndTheHostCarriesOn) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  // The 48-byte DREAM_POSES: num_robots = 2^28 after the fingerprint, utime and step.
  std::vector<uint8_t> poses(48, 0);
  const robot_poses_t empty{};
  empty.encode(poses.data(), 0, empty.getEncodedSize());
  poses[24] = 0x10;
  bus_.Publish(lcm::kPosesChannel, poses.data(), static_cast<int>(poses.size()));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();
  EXPECT_EQ(host.bad_messages().count(lcm::kPosesChannel), 1);
  EXPECT_EQ(calls, 1);  // the real step after the forged one was answered
}

/// Routes spdlog's default logger into a string while alive.
class CapturedLog {
 public:
  CapturedLog() : previous_(spdlog::default_logger()) {
    spdlog::set_default_logger(
        std::make_shared<spdlog::logger>("captured", std::make_shared<spdlog::sinks::ostream_sink_st>(text_)));
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::shared_ptr<spdlog::logger> previous_;
};

TEST_F(AgentHostTest, UndecodablePayloadsAreLoggedBySenderFirstThenEveryHundredthAndTotalledAtTheEnd) {
  CapturedLog log;
  {
    int calls = 0;
    std::vector<std::unique_ptr<RobotAgent>> agents;
    agents.push_back(MakeAgent(0, &calls));
    agents.push_back(MakeAgent(1, &calls, nullptr, /*name_bad_senders=*/false));
    agent_host::AgentHost host(bus_, std::move(agents), 1);
    const radio_message_t bad = UndecodableRadioMessage(5);
    lcm::Publish(bus_, lcm::RadioChannel(5), bad);
    // The mailbox keeps a sender's latest message, so the robots hear (and
    // reject) it again at every radio round: steps 2..101 make 100.
    for (int64_t step = 2; step <= 101; ++step) {
      lcm::Publish(bus_, lcm::kPosesChannel, Poses(step, 6));
      Drain();
    }
    EXPECT_EQ(host.agent(0).robot().bad_radio_messages(), 100);
    EXPECT_EQ(host.bad_radio_payloads(0).count(lcm::RadioChannel(5)), 100);
    EXPECT_EQ(host.bad_radio_payloads(0).total(), 100);
    EXPECT_EQ(host.bad_radio_payloads(1).count(agent_host::AgentHost::kUnknownSenderChannel), 100);
    EXPECT_EQ(host.bad_messages().total(), 0);  // the LCM message itself was fine
    const std::string during = log.text();
    EXPECT_NE(during.find("DREAM_RADIO_5: dropped bad message #1: robot 0: payload did not decode"), std::string::npos)
        << during;
    EXPECT_NE(during.find("DREAM_RADIO_5: dropped bad message #100: robot 0: payload did not decode"),
              std::string::npos)
        << during;
    EXPECT_EQ(during.find("#2:"), std::string::npos) << during;
    EXPECT_NE(during.find("DREAM_RADIO_<unknown sender>: dropped bad message #1: robot 1: payload did not decode"),
              std::string::npos)
        << during;
    EXPECT_EQ(during.find("did not decode: DREAM_RADIO"), std::string::npos);  // no totals before the end
  }
  const std::string after = log.text();
  EXPECT_NE(after.find("robot 0 dropped 100 radio payload(s) that did not decode: DREAM_RADIO_5 x100"),
            std::string::npos)
      << after;
  EXPECT_NE(after.find("robot 1 dropped 100 radio payload(s) that did not decode: DREAM_RADIO_<unknown sender> x100"),
            std::string::npos)
      << after;
}

TEST_F(AgentHostTest, AHostWhoseRobotsDecodedEverythingLogsNoTotals) {
  CapturedLog log;
  {
    int calls = 0;
    std::vector<std::unique_ptr<RobotAgent>> agents;
    agents.push_back(MakeAgent(0, &calls));
    agents.push_back(MakeAgent(1, &calls));
    agent_host::AgentHost host(bus_, std::move(agents), 1);
    for (int64_t step = 1; step <= 3; ++step) {
      lcm::Publish(bus_, lcm::kPosesChannel, Poses(step, 2));
      Drain();
    }
    EXPECT_EQ(Counting(host, 0).heard_ids, (std::vector<int>{1}));
    EXPECT_EQ(host.bad_radio_payloads(0).total(), 0);
  }
  EXPECT_EQ(log.text().find("did not decode"), std::string::npos) << log.text();
}

TEST_F(AgentHostTest, MalformedPosesAndMissingRobotsAreCountedNotFatal) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(5, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  const char garbage[] = "garbage";
  bus_.Publish(lcm::kPosesChannel, garbage, sizeof(garbage));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));  // robot 5 is not in a 3-robot run
  Drain();
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(host.bad_messages().count(lcm::kPosesChannel), 2);
}

// Agents started with another experiment's config (10 robots) against a
// world of 3 would drive its robots with the wrong controller: they never
// join it, and Run() says why instead of "no DREAM_POSES".
TEST_F(AgentHostTest, AWorldOfAnotherRobotCountIsNeverJoined) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 1);
  host.ExpectWorldOfRobots(10);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 3));
  Drain();
  EXPECT_EQ(calls, 0);
  EXPECT_TRUE(commands_.empty());
  EXPECT_FALSE(host.follower().joined());
  EXPECT_EQ(host.bad_messages().count(lcm::kPosesChannel), 1);
  const std::atomic<bool> stop{false};
  EXPECT_FALSE(host.Run(stop, 0.05));  // nothing but that world: gives up as a silent world would
  // The world of its own count is joined as ever.
  host.ExpectWorldOfRobots(3);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 3));
  Drain();
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(host.follower().joined());
}

TEST_F(AgentHostTest, AForgedFarStepOrAnotherRunsFinishNeitherFreezesNorEndsTheRobots) {
  int calls = 0;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  agents.push_back(MakeAgent(0, &calls));
  agent_host::AgentHost host(bus_, std::move(agents), 9);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(1, 2));
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(int64_t{1} << 40, 2));  // forged: would freeze the Timer
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 2, /*run_id=*/0xbad));
  run_status_t finished{};
  finished.run_id = 0xbad;
  finished.step = 2;
  finished.state = run_status_t::FINISHED;
  lcm::Publish(bus_, lcm::kStatusChannel, finished);
  lcm::Publish(bus_, lcm::kPosesChannel, Poses(2, 2));
  Drain();
  EXPECT_EQ(calls, 2);  // steps 1 and 2 of the run joined
  ASSERT_EQ(commands_.size(), 2U);
  EXPECT_EQ(commands_[1].step, 2);
  EXPECT_EQ(commands_[1].run_id, kRunId);
  EXPECT_FALSE(host.world_finished());
  EXPECT_EQ(host.follower().other_runs(), std::set<int64_t>{0xbad});
  // A radio message from the future would shadow the sender's real ones.
  radio_message_t future{};
  future.run_id = kRunId;
  future.step = 1000;
  future.sender_id = 1;
  lcm::Publish(bus_, lcm::RadioChannel(1), future);
  Drain();
  EXPECT_EQ(host.bad_messages().count(lcm::RadioChannel(1)), 1);
  finished.run_id = kRunId;
  lcm::Publish(bus_, lcm::kStatusChannel, finished);
  Drain();
  EXPECT_TRUE(host.world_finished());
}

TEST(ControllerFactoryTest, UnknownKindsAndBadSectionsAreClearErrors) {
  auto error_of = [](const std::string& yaml, int robots) {
    try {
      agent_host::ControllerFactory(config::ConfigNode::LoadString(yaml, "c.yaml").Required("controller"), robots, 1);
    } catch (const config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("controller: {kind: teleport}\n", 1)
                .find("unknown controller kind 'teleport'; known kinds: "
                      "go_to_goal"),
            std::string::npos);
  EXPECT_NE(error_of("controller: {kind: go_to_goal, goals: [[0, 0]]}\n", 2).find("one [x, y] goal per robot (2)"),
            std::string::npos);
  EXPECT_NE(error_of("controller: {kind: go_to_goal, goals: [[0, 0]], gain: -1}\n", 1)
                .find("controller.gain: must be > 0, got -1"),
            std::string::npos);
  EXPECT_EQ(error_of("controller: {kind: go_to_goal, goals: [[0, 0], [1, 0]]}\n", 2), "");
  const std::string base = "controller:\n  kind: go_to_goal\n  goals: [[0, 0], [1, 0]]\n";
  EXPECT_NE(error_of(base + "  sensors: [{kind: sonar}]\n", 2).find("unknown sensor kind 'sonar'"), std::string::npos);
  EXPECT_NE(error_of(base + "  sensors: [{kind: odometry, period_steps: 0}]\n", 2).find("must be >= 1, got 0"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  sensors: [{kind: odometry, noise_std: -0.1}]\n", 2)
                .find("controller.sensors[0].noise_std: must be >= 0, got -0.1"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  radio: {kind: carrier_pigeon}\n", 2).find("unknown radio kind 'carrier_pigeon'"),
            std::string::npos);
  EXPECT_NE(
      error_of(base + "  radio: {kind: graph, graph: [[0, 1, 0], [1, 0, 0], [0, 0, 0]]}\n", 2).find("must be 2x2"),
      std::string::npos);
  EXPECT_NE(error_of(base + "  radio: {kind: range, loss_probability: 1.5}\n", 2)
                .find("controller.radio.loss_probability: must be in [0, 1), got 1.5"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  robot: {period_steps: [1, 2, 3]}\n", 2).find("one per robot (2), got 3"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  colour: red\n", 2).find("colour: unknown key for kind go_to_goal"), std::string::npos);
}

std::string FactoryError(const std::string& yaml, int robots) {
  try {
    agent_host::ControllerFactory(config::ConfigNode::LoadString(yaml, "c.yaml").Required("controller"), robots, 1);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no config error for:\n" << yaml;
  return "";
}

// Each mistake in the common parts names its file, line, key and value.
TEST(ControllerFactoryTest, BadPeriodsDelaysNoiseAndRadioImpairmentsNameKeyAndValue) {
  const std::string base = "controller:\n  kind: go_to_goal\n  goals: [[0, 0], [1, 0]]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"  robot: {period_steps: 0}\n", "c.yaml:4: controller.robot.period_steps: must be >= 1, got 0"},
      {"  robot: {period_steps: [2, -3]}\n", "c.yaml:4: controller.robot.period_steps[1]: must be >= 1, got -3"},
      {"  robot: {period_steps: 4294967297}\n", "controller.robot.period_steps: must be <= 2147483647, got 4294967297"},
      {"  robot: {start_delay_steps: -1}\n", "c.yaml:4: controller.robot.start_delay_steps: must be >= 0, got -1"},
      {"  robot: {vel_gain: 0}\n", "c.yaml:4: controller.robot.vel_gain: must be > 0, got 0"},
      {"  robot: {ang_gain: -3}\n", "c.yaml:4: controller.robot.ang_gain: must be > 0, got -3"},
      {"  radio: {kind: range, period_steps: 0}\n", "c.yaml:4: controller.radio.period_steps: must be >= 1, got 0"},
      {"  sensors: [{kind: odometry}, {kind: movement, noise_std: -0.01}]\n",
       "c.yaml:4: controller.sensors[1].noise_std: must be >= 0, got -0.01"},
      {"  sensors: [{kind: obstacle, noise_std: -2}]\n",
       "c.yaml:4: controller.sensors[0].noise_std: must be >= 0, got -2"},
      {"  sensors: [{kind: movement, field_of_view_rad: 7}]\n",
       "c.yaml:4: controller.sensors[0].field_of_view_rad: must be in (0, 2 pi = 6.2832], got 7"},
      {"  sensors: [{kind: obstacle, range_m: 0}]\n", "c.yaml:4: controller.sensors[0].range_m: must be > 0, got 0"},
      {"  radio: {kind: range, loss_probability: 1.0}\n",
       "c.yaml:4: controller.radio.loss_probability: must be in [0, 1), got 1"},
      {"  radio: {kind: range, loss_probability: -0.1}\n",
       "c.yaml:4: controller.radio.loss_probability: must be in [0, 1), got -0.1"},
      {"  radio: {kind: range, delay_steps: -1}\n", "c.yaml:4: controller.radio.delay_steps: must be >= 0, got -1"},
      {"  radio: {kind: range, range_m: -1}\n", "c.yaml:4: controller.radio.range_m: must be > 0, got -1"},
      // A key of another radio kind would be ignored: it is an error instead.
      {"  radio: {kind: range, leaders: [0]}\n",
       "c.yaml:4: controller.radio.kind: a radio of kind range has no `leaders`"},
      {"  radio: {kind: graph, graph: [[0, 1], [1, 0]], range_m: 1}\n",
       "c.yaml:4: controller.radio.kind: a radio of kind graph has no `range_m`; its keys: kind, period_steps, graph, "
       "loss_probability, delay_steps"},
      {"  radio: {kind: none, range_m: 1}\n", "c.yaml:4: controller.radio.kind: a radio of kind none has no `range_m`"},
  };
  for (const auto& [yaml, expected] : cases) {
    const std::string error = FactoryError(base + yaml, 2);
    EXPECT_NE(error.find(expected), std::string::npos) << "config line: " << yaml << "error: " << error;
  }
}

// A stress graph in two pieces: followers 3 and 4 linked only to each other
// can never learn where the leaders are.
TEST(ControllerFactoryTest, ADisconnectedStressGraphIsRejectedNamingTheUnreachableRobot) {
  const std::string yaml =
      "controller:\n"
      "  kind: affine_formation\n"
      "  nominal_positions: [[0.4, 0.0], [0.0, 0.4], [0.0, -0.4], [-0.4, 0.2], [-0.4, -0.2]]\n"
      "  maneuver: [{step: 0}]\n"
      "  radio:\n"
      "    kind: role\n"
      "    leaders: [0, 1, 2]\n"
      "    graph:\n"
      "      - [0, 1, 1, 0, 0]\n"
      "      - [1, 0, 1, 0, 0]\n"
      "      - [1, 1, 0, 0, 0]\n"
      "      - [0, 0, 0, 0, 1]\n"
      "      - [0, 0, 0, 1, 0]\n";
  const std::string error = FactoryError(yaml, 5);
  EXPECT_NE(error.find("c.yaml:9: controller.radio.graph: the graph is not connected: robot 3 cannot be reached"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace dream::agents
