#include "dream/run_log/message_json.h"

#include <gtest/gtest.h>

#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "../support/encoded_message.h"

namespace dream::run_log {
namespace {

using dream::testing::Encoded;

robot_poses_t TwoRobots() {
  robot_poses_t poses;
  poses.utime = 33000;
  poses.step = 1;
  poses.run_id = 0xabc;
  poses.num_robots = 2;
  poses.x = {0.5, -0.25};
  poses.y = {0.1, 0.2};
  poses.theta = {3.0, -1.5};
  poses.v = {0.1, 0.0};
  poses.w = {0.0, 0.5};
  return poses;
}

TEST(MessageJson, PosesDecodeToTheirFieldsInOrder) {
  const MessageJson json(Encoded(TwoRobots()));
  ASSERT_EQ(json.outcome(), MessageJson::Outcome::kDecoded) << json.problem();
  EXPECT_EQ(json.type(), "robot_poses_t");
  EXPECT_EQ(
      json.fields().dump(),
      R"({"utime":33000,"step":1,"run_id":"0000000000000abc","num_robots":2,"x":[0.5,-0.25],"y":[0.1,0.2],"theta":[3.0,-1.5],)"
      R"("v":[0.1,0.0],"w":[0.0,0.5]})");
}

TEST(MessageJson, RadioPayloadIsHex) {
  radio_message_t radio;
  radio.utime = 132000;
  radio.step = 4;
  radio.run_id = 1;
  radio.sender_id = 3;
  radio.agent_id = 99;
  radio.payload = {0x00, 0xab, 0x10, 0xff};
  radio.payload_size = 4;
  const MessageJson json(Encoded(radio));
  ASSERT_EQ(json.outcome(), MessageJson::Outcome::kDecoded) << json.problem();
  EXPECT_EQ(json.fields()["payload"], "00ab10ff");
  EXPECT_EQ(json.fields()["sender_id"], 3);
}

TEST(MessageJson, AppliedCommandsSayWhichAgentDroveEachRobot) {
  applied_commands_t applied{};
  applied.step = 7;
  applied.run_id = 0x10;
  applied.num_robots = 2;
  applied.applied_agent_id = {42, 0};
  applied.commanded_v = {0.1, 0.0};
  applied.commanded_w = {0.5, 0.0};
  applied.conflicts = {1, 0};
  const MessageJson json(Encoded(applied));
  ASSERT_EQ(json.outcome(), MessageJson::Outcome::kDecoded) << json.problem();
  EXPECT_EQ(json.type(), "applied_commands_t");
  EXPECT_EQ(json.fields()["applied_agent_id"].dump(), "[42,0]");
  EXPECT_EQ(json.fields()["conflicts"].dump(), "[1,0]");
  EXPECT_EQ(json.fields()["run_id"], "0000000000000010");
}

TEST(MessageJson, CutShortIsUndecodableWithTheTypeAndWhy) {
  std::vector<uint8_t> bytes = Encoded(TwoRobots());
  bytes.resize(bytes.size() - 5);
  const MessageJson json(bytes);
  EXPECT_EQ(json.outcome(), MessageJson::Outcome::kUndecodable);
  EXPECT_EQ(json.type(), "robot_poses_t");
  EXPECT_FALSE(json.problem().empty());
}

TEST(MessageJson, AForgedCountIsRefusedWithoutDecoding) {
  std::vector<uint8_t> bytes = Encoded(TwoRobots());
  // num_robots (after the 8-byte fingerprint, utime, step and run_id) set to 2^31 - 1.
  bytes[32] = 0x7f;
  bytes[33] = bytes[34] = bytes[35] = 0xff;
  const MessageJson json(bytes);
  EXPECT_EQ(json.outcome(), MessageJson::Outcome::kUndecodable);
}

TEST(MessageJson, OtherProgramsMessagesAreUnknown) {
  EXPECT_EQ(MessageJson(std::vector<uint8_t>(16, 0x42)).outcome(), MessageJson::Outcome::kUnknownType);
  EXPECT_EQ(MessageJson(std::vector<uint8_t>{1, 2, 3}).outcome(), MessageJson::Outcome::kUnknownType);
}

}  // namespace
}  // namespace dream::run_log
