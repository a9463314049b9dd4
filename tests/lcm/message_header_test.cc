// lcm::MessageHeader and the channel names of lcm/channels.h against what
// lcm-gen writes and what the world and agents send on.
#include "dream/lcm/message_header.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/radio_message_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::lcm {
namespace {

template <typename Message>
std::vector<uint8_t> Encoded(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// Values whose bytes all differ, so an offset one off reads something else.
constexpr int64_t kUtime = 0x0102030405060708;
constexpr int64_t kStep = 0x1112131415161718;
constexpr int64_t kRunId = -0x2122232425262728;
constexpr int64_t kAgentId = 0x3132333435363738;

TEST(MessageHeaderTest, ReadsWhatLcmGenWroteForEveryMessageWithTheHeader) {
  velocity_command_t command{};
  command.utime = kUtime;
  command.step = kStep;
  command.run_id = kRunId;
  command.robot_id = 3;
  command.agent_id = kAgentId;
  radio_message_t radio{};
  radio.utime = kUtime;
  radio.step = kStep;
  radio.run_id = kRunId;
  radio.sender_id = 3;
  radio.agent_id = kAgentId;
  robot_poses_t poses{};
  poses.utime = kUtime;
  poses.step = kStep;
  poses.run_id = kRunId;
  for (const auto& [bytes, fingerprint] :
       {std::pair{Encoded(command), velocity_command_t::getHash()},
        std::pair{Encoded(radio), radio_message_t::getHash()}, std::pair{Encoded(poses), robot_poses_t::getHash()}}) {
    const std::optional<MessageHeader> header = MessageHeader::Read(bytes.data(), bytes.size());
    ASSERT_TRUE(header.has_value());
    EXPECT_EQ(header->fingerprint, fingerprint);
    EXPECT_EQ(header->utime, kUtime);
    EXPECT_EQ(header->step, kStep);
    EXPECT_EQ(header->run_id, kRunId);
  }
  const std::vector<uint8_t> command_bytes = Encoded(command);
  EXPECT_EQ(MessageHeader::AgentIdOf(command_bytes.data(), command_bytes.size()), kAgentId);
  const std::vector<uint8_t> radio_bytes = Encoded(radio);
  EXPECT_EQ(MessageHeader::AgentIdOf(radio_bytes.data(), radio_bytes.size()), kAgentId);
  EXPECT_EQ(MessageHeader::Int64At(command_bytes.data(), MessageHeader::kRobotIdAt) >> 32, 3);  // the int32 robot_id
}

TEST(MessageHeaderTest, BytesTooShortForTheHeaderSayNothing) {
  robot_fault_t fault{};
  fault.run_id = kRunId;
  const std::vector<uint8_t> bytes = Encoded(fault);
  EXPECT_FALSE(MessageHeader::Read(bytes.data(), MessageHeader::kBytes - 1).has_value());
  EXPECT_TRUE(MessageHeader::Read(bytes.data(), MessageHeader::kBytes).has_value());
  EXPECT_FALSE(MessageHeader::AgentIdOf(bytes.data(), MessageHeader::kAgentIdAt + 7).has_value());
  EXPECT_FALSE(MessageHeader::Read(nullptr, 100).has_value());
}

TEST(ChannelsTest, AnAgentsChannelsAreParsedByKindAndRobotAndNothingElseIs) {
  const std::optional<AgentChannel> command = ParseAgentChannel(CommandChannel(12));
  ASSERT_TRUE(command.has_value());
  EXPECT_EQ(command->kind, AgentChannel::Kind::kCommand);
  EXPECT_EQ(command->robot_id, 12);
  EXPECT_EQ(ParseAgentChannel(RadioChannel(0))->kind, AgentChannel::Kind::kRadio);
  EXPECT_EQ(ParseAgentChannel(FaultChannel(999999))->robot_id, 999999);
  for (const char* not_an_agents : {"DREAM_POSES", "DREAM_CMD_", "DREAM_CMD_1234567", "DREAM_CMD_-1", "DREAM_CMD_1x",
                                    "DREAM_LAB_CMD_1", "DREAM_RADIO_<unknown sender>", "dream_CMD_1"}) {
    EXPECT_FALSE(ParseAgentChannel(not_an_agents).has_value()) << not_an_agents;
  }
  EXPECT_EQ(LabCommandChannel(4), "DREAM_LAB_CMD_4");
  EXPECT_EQ(RobotIdFromChannel(LabCommandChannel(4), kLabCommandChannelPrefix), 4);
}

}  // namespace
}  // namespace dream::lcm
