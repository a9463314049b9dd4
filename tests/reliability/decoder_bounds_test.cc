// Forged counts and lengths against every dream decoder: each is refused
// before the lcm-gen decoder allocates, whatever the count claims.
#include <gtest/gtest.h>

#include <climits>
#include <map>
#include <random>

#include "allocation_watch.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/message_limits.h"
#include "dream/lcm/wire_layout_of.h"
#include "dream/lcm/wire_text.h"
#include "dream/obstacles_t.hpp"
#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/velocity_command_t.hpp"
#include "sample_messages.h"

namespace dream::testing {
namespace {

using lcm::MessageLimits;

// Where each sample's count or string length sits: after the 8-byte
// fingerprint and the fixed fields before it.
const std::map<std::string, size_t> kCountOffset = {
    {"robot_poses_t", 8 + 24},         {"obstacles_t", 8 + 24},   {"run_status_t", 8 + 8 + 8 + 8 + 1 + 4 + 48},
    {"radio_message_t", 8 + 36},       {"robot_fault_t", 8 + 36}, {"applied_commands_t", 8 + 24},
    {"run_verdict_t", 8 + 24 + 14},     // goal_text's length
    {"drawing_t", 8 + 24 + 4 + 8 + 4},  // num_shapes
    {"robot_commands_t", 8 + 24 + 8},   // num_commands
};

// Counts an attacker would pick: huge, negative, just over the limit, and
// ones whose byte size wraps a 32-bit int to something small
// (40 * 0x6666667 = 2^32 + 24: robot_poses_t's five doubles per robot).
const std::vector<int32_t> kForgedCounts = {1 << 28,   -1,         INT_MAX,    INT_MIN,
                                            0x6666667, 0x20000000, 0x40000000, MessageLimits::kRobots + 1};

// Nothing a forged message makes us allocate may exceed this.
constexpr size_t kMaxAllocationBytes = 64 * 1024;

void PutBigEndian32(std::vector<uint8_t>* bytes, size_t at, int32_t value) {
  const auto bits = static_cast<uint32_t>(value);
  for (size_t i = 0; i < 4; ++i) (*bytes)[at + i] = static_cast<uint8_t>(bits >> (24 - 8 * i));
}

TEST(DecoderBounds, EverySampleDecodesAsItsOwnTypeOnly) {
  for (const EncodedMessage& sample : SampleMessages()) {
    for (const auto& [type, decode] : Decoders()) {
      EXPECT_EQ(decode(sample.bytes.data(), static_cast<int>(sample.bytes.size())), type == sample.type)
          << sample.type << " decoded as " << type;
    }
  }
}

TEST(DecoderBounds, LayoutsMatchTheGeneratedEncodings) {
  // A default message: every count zero, every string empty.
  EXPECT_EQ(lcm::WireLayoutOf<robot_poses_t>().MinimumBytes(), robot_poses_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<obstacles_t>().MinimumBytes(), obstacles_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<run_status_t>().MinimumBytes(), run_status_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<velocity_command_t>().MinimumBytes(), velocity_command_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<radio_message_t>().MinimumBytes(), radio_message_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<robot_fault_t>().MinimumBytes(), robot_fault_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<applied_commands_t>().MinimumBytes(), applied_commands_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<run_verdict_t>().MinimumBytes(), run_verdict_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<drawing_t>().MinimumBytes(), drawing_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<robot_busy_t>().MinimumBytes(), robot_busy_t{}.getEncodedSize());
  EXPECT_EQ(lcm::WireLayoutOf<robot_commands_t>().MinimumBytes(), robot_commands_t{}.getEncodedSize());
}

TEST(DecoderBounds, TheLargestLegalMessagesDecode) {
  robot_poses_t poses{};
  poses.num_robots = MessageLimits::kRobots;
  poses.x = poses.y = poses.theta = poses.v = poses.w = std::vector<double>(MessageLimits::kRobots, 0.5);
  std::vector<uint8_t> bytes = Encoded(poses);
  robot_poses_t back;
  EXPECT_TRUE(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &back));
  EXPECT_EQ(back.x.size(), static_cast<size_t>(MessageLimits::kRobots));

  radio_message_t radio{};
  radio.payload_size = MessageLimits::kRadioPayloadBytes;
  radio.payload.assign(static_cast<size_t>(radio.payload_size), 7);
  bytes = Encoded(radio);
  radio_message_t radio_back;
  EXPECT_TRUE(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &radio_back));

  robot_commands_t commands{};
  commands.num_commands = MessageLimits::kRobots;
  commands.robot_id.assign(MessageLimits::kRobots, 1);
  commands.v = commands.w = std::vector<double>(MessageLimits::kRobots, 0.1);
  commands.done.assign(MessageLimits::kRobots, 1);
  bytes = Encoded(commands);
  robot_commands_t commands_back;
  EXPECT_TRUE(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &commands_back));
  bytes[bytes.size() - 1] = 2;  // a boolean that is neither 0 nor 1
  EXPECT_FALSE(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &commands_back));

  robot_fault_t fault{};
  fault.detail.assign(static_cast<size_t>(MessageLimits::kDetailBytes), 'x');
  bytes = Encoded(fault);
  robot_fault_t fault_back;
  EXPECT_TRUE(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &fault_back));
  fault.detail += 'x';
  bytes = Encoded(fault);
  EXPECT_FALSE(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &fault_back));
}

TEST(DecoderBounds, TheRobotLimitCoversEveryRunTheConfigAllows) {
  EXPECT_GE(MessageLimits::kRobots, robotarium::RobotariumConstants::kMaxRobotsInSimulation);
}

// A sim_only run has up to 128 robots (50 otherwise), and dream view draws
// any DREAM-format stream up to that bound (issue 25: a 30 Hz stream of 100 robots).
TEST(DecoderBounds, AHundredRobotStreamDecodesAndOneOverTheBoundDoesNot) {
  for (const int32_t robots : {100, MessageLimits::kRobots, MessageLimits::kRobots + 1}) {
    robot_poses_t poses{};
    poses.num_robots = robots;
    poses.x = poses.y = poses.theta = poses.v = poses.w = std::vector<double>(static_cast<size_t>(robots), 0.5);
    run_status_t status{};
    status.num_lost = robots;
    status.lost_robot_ids.assign(static_cast<size_t>(robots), 1);
    std::vector<uint8_t> bytes = Encoded(poses);
    robot_poses_t poses_back;
    EXPECT_EQ(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &poses_back), robots <= MessageLimits::kRobots)
        << robots << " robots";
    bytes = Encoded(status);
    run_status_t status_back;
    EXPECT_EQ(lcm::Decode(bytes.data(), static_cast<int>(bytes.size()), &status_back), robots <= MessageLimits::kRobots)
        << robots << " lost robots";
  }
}

TEST(DecoderBounds, TheObstacleLimitIsTheConfigsLimit) {
  EXPECT_EQ(static_cast<size_t>(MessageLimits::kObstacles), run_config::RunConfig::kMaxObstacles);
}

TEST(DecoderBounds, ForgedCountsAreRefusedWithoutLargeAllocations) {
  for (const EncodedMessage& sample : SampleMessages()) {
    const auto offset = kCountOffset.find(sample.type);
    if (offset == kCountOffset.end()) continue;  // velocity_command_t has no count
    for (int32_t count : kForgedCounts) {
      // As sent, then with as many extra bytes as a datagram could carry.
      for (size_t extra : {size_t{0}, size_t{24}, size_t{4096}}) {
        std::vector<uint8_t> forged = sample.bytes;
        PutBigEndian32(&forged, offset->second, count);
        forged.resize(forged.size() + extra, 0);
        const AllocationWatch watch;
        EXPECT_FALSE(Decoders().at(sample.type)(forged.data(), static_cast<int>(forged.size())))
            << sample.type << " with count " << count << " and " << extra << " extra bytes";
        EXPECT_LE(watch.largest(), kMaxAllocationBytes) << sample.type << " with count " << count;
      }
    }
  }
}

TEST(DecoderBounds, TheIssuesFortyEightBytePosesDatagramIsRefused) {
  // 8 fingerprint + 24 utime/step/run_id + 4 count (2^28) + 12 bytes of "poses".
  robot_poses_t empty{};
  std::vector<uint8_t> datagram = Encoded(empty);
  datagram.resize(48, 0);
  PutBigEndian32(&datagram, kCountOffset.at("robot_poses_t"), 1 << 28);
  robot_poses_t poses;
  const AllocationWatch watch;
  const std::optional<std::string> problem = lcm::DecodeProblem(datagram.data(), 48, &poses);
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("count 268435456"), std::string::npos) << *problem;
  EXPECT_LE(watch.largest(), kMaxAllocationBytes);
}

TEST(DecoderBounds, EveryTruncationAndExtensionIsRefused) {
  for (const EncodedMessage& sample : SampleMessages()) {
    for (size_t cut = 0; cut < sample.bytes.size(); ++cut) {
      EXPECT_FALSE(Decoders().at(sample.type)(sample.bytes.data(), static_cast<int>(cut)))
          << sample.type << " cut to " << cut << " bytes";
    }
    std::vector<uint8_t> longer = sample.bytes;
    longer.push_back(0);
    EXPECT_FALSE(Decoders().at(sample.type)(longer.data(), static_cast<int>(longer.size()))) << sample.type;
  }
}

TEST(DecoderBounds, StringLengthsOutsideTheBytesAreRefused) {
  // robot_fault_t's detail length: 0 (no NUL), negative, past the end, huge.
  const EncodedMessage fault = SampleMessages()[5];
  ASSERT_EQ(fault.type, "robot_fault_t");
  for (int32_t length : {0, -1, INT_MIN, INT_MAX, 1 << 28, 1000}) {
    std::vector<uint8_t> forged = fault.bytes;
    PutBigEndian32(&forged, kCountOffset.at("robot_fault_t"), length);
    robot_fault_t message;
    const AllocationWatch watch;
    EXPECT_TRUE(lcm::DecodeProblem(forged.data(), static_cast<int>(forged.size()), &message).has_value())
        << "detail length " << length;
    EXPECT_LE(watch.largest(), kMaxAllocationBytes);
  }
}

// A string must be UTF-8 text ending in its one NUL: lcm-gen's decoder drops
// the last byte unseen and its encoder stops at the first NUL, and text that
// is not UTF-8 cannot be written to summary.json (the JSON library throws).
TEST(DecoderBounds, StringsMustBeUtf8TextEndingInTheirOneNul) {
  robot_fault_t fault;
  fault.detail = "bad \xC3\xA9 \xE2\x86\x92 \xF0\x9F\xA4\x96";  // é, an arrow, a robot: text
  std::vector<uint8_t> bytes(static_cast<size_t>(fault.getEncodedSize()));
  ASSERT_EQ(fault.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  robot_fault_t decoded;
  ASSERT_FALSE(lcm::DecodeProblem(bytes.data(), static_cast<int>(bytes.size()), &decoded).has_value());
  EXPECT_EQ(decoded.detail, fault.detail);

  const size_t text = kCountOffset.at("robot_fault_t") + 4;
  const size_t nul = bytes.size() - 1;
  const std::vector<std::pair<std::pair<size_t, uint8_t>, std::string>> forgeries = {
      {{text + 1, 0xFF}, "is not UTF-8 text (byte " + std::to_string(text + 1) + " is 255)"},
      {{text + 5, 0xC3}, "is not UTF-8 text (byte " + std::to_string(text + 4) + " is 195)"},  // é's lead, then a lead
      {{text + 4, 0x80}, "is not UTF-8 text (byte " + std::to_string(text + 4) + " is 128)"},  // a lone continuation
      {{text + 2, 0x00}, "holds a NUL before its end"},
      {{nul, 'x'}, "does not end in a NUL"},
  };
  for (const auto& [change, problem] : forgeries) {
    SCOPED_TRACE(problem);
    std::vector<uint8_t> forged = bytes;
    forged[change.first] = change.second;
    const std::optional<std::string> refused =
        lcm::DecodeProblem(forged.data(), static_cast<int>(forged.size()), &decoded);
    ASSERT_TRUE(refused.has_value());
    EXPECT_NE(refused->find(problem), std::string::npos) << *refused;
  }
  // Overlong forms and surrogates are not UTF-8 either.
  for (const std::string& bad : {std::string("\xC0\xAF"), std::string("\xE0\x80\xAF"), std::string("\xED\xA0\x80"),
                                 std::string("\xF4\x90\x80\x80")}) {
    robot_fault_t forged_fault;
    forged_fault.detail = "x" + bad;
    std::vector<uint8_t> forged(static_cast<size_t>(forged_fault.getEncodedSize()));
    forged_fault.encode(forged.data(), 0, static_cast<int>(forged.size()));
    EXPECT_TRUE(lcm::DecodeProblem(forged.data(), static_cast<int>(forged.size()), &decoded).has_value());
  }
}

// lcm-gen reads any non-zero byte as true and writes it back as 1: a boolean
// byte must be 0 or 1 for a message to mean one thing.
TEST(DecoderBounds, BooleansAreZeroOrOne) {
  velocity_command_t command;
  command.done = true;
  std::vector<uint8_t> bytes(static_cast<size_t>(command.getEncodedSize()));
  command.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  velocity_command_t decoded;
  ASSERT_FALSE(lcm::DecodeProblem(bytes.data(), static_cast<int>(bytes.size()), &decoded).has_value());
  EXPECT_TRUE(decoded.done);
  bytes.back() = 2;
  const std::optional<std::string> problem = lcm::DecodeProblem(bytes.data(), static_cast<int>(bytes.size()), &decoded);
  ASSERT_TRUE(problem.has_value());
  EXPECT_EQ(*problem, "boolean at byte " + std::to_string(bytes.size() - 1) + " is 2, not 0 or 1");
}

// What we send that quotes what we were given (a path, a URL, a controller's
// error) goes through WireText::Of: any bytes come out as a string the
// decoders accept, cut between characters.
TEST(DecoderBounds, WireTextMakesAnyBytesAnAcceptedString) {
  EXPECT_EQ(lcm::WireText::Of("caf\xC3\xA9", 100), "caf\xC3\xA9");
  EXPECT_EQ(lcm::WireText::Of(std::string("a\0b\xFF\xC3", 5), 100), "a\\0b??");
  EXPECT_EQ(lcm::WireText::Of("\xC3\xA9\xC3\xA9", 3), "\xC3\xA9");  // not half an é
  std::mt19937 random(7);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string bytes(static_cast<size_t>(random() % 40), '\0');
    for (char& c : bytes) c = static_cast<char>(random() % 256);
    robot_fault_t fault;
    fault.detail = lcm::WireText::Of(bytes, 24);
    ASSERT_LE(fault.detail.size(), 24u);
    std::vector<uint8_t> encoded(static_cast<size_t>(fault.getEncodedSize()));
    ASSERT_EQ(fault.encode(encoded.data(), 0, static_cast<int>(encoded.size())), static_cast<int>(encoded.size()));
    robot_fault_t decoded;
    const std::optional<std::string> problem =
        lcm::DecodeProblem(encoded.data(), static_cast<int>(encoded.size()), &decoded);
    ASSERT_FALSE(problem.has_value()) << *problem;
  }
}

TEST(DecoderBounds, NegativeSizesAndNullBuffersAreRefused) {
  for (const auto& [type, decode] : Decoders()) {
    EXPECT_FALSE(decode(nullptr, 0)) << type;
    EXPECT_FALSE(decode(nullptr, 100)) << type;
    const EncodedMessage sample = SampleMessages()[0];
    EXPECT_FALSE(decode(sample.bytes.data(), -1)) << type;
  }
}

TEST(DecoderBounds, AnUndecodableMessageNamesItsSenderWhenTheBytesReachIt) {
  const EncodedMessage command = SampleMessages()[3];
  ASSERT_EQ(command.type, "velocity_command_t");
  std::vector<uint8_t> truncated(command.bytes.begin(), command.bytes.end() - 1);
  EXPECT_EQ(lcm::WireLayoutOf<velocity_command_t>().AgentIdOf(truncated.data(), static_cast<int>(truncated.size())),
            0x1234567890);
  EXPECT_FALSE(lcm::WireLayoutOf<velocity_command_t>().AgentIdOf(truncated.data(), 20).has_value());
  EXPECT_FALSE(lcm::WireLayoutOf<robot_poses_t>().AgentIdOf(truncated.data(), 40).has_value());
}

TEST(BadMessageLogBounds, ChannelsPastTheCapShareOneEntry) {
  lcm::BadMessageLog log;
  const size_t channels = lcm::BadMessageLog::kMaxChannels + 1000;
  for (size_t i = 0; i < channels; ++i) log.Report("FORGED_" + std::to_string(i), "test", static_cast<int64_t>(i));
  EXPECT_EQ(log.per_channel().size(), lcm::BadMessageLog::kMaxChannels + 1);
  EXPECT_EQ(log.count(lcm::BadMessageLog::kOtherChannels), 1000);
  EXPECT_EQ(log.count("FORGED_0"), 1);
  EXPECT_EQ(log.count("FORGED_" + std::to_string(channels - 1)), 0);  // counted under the shared entry
  EXPECT_EQ(log.total(), static_cast<long>(channels));
  EXPECT_EQ(log.senders().at(lcm::BadMessageLog::kOtherChannels).size(), lcm::BadMessageLog::kMaxSendersPerChannel);
}

TEST(BadMessageLogBounds, SendersPerChannelAreCapped) {
  lcm::BadMessageLog log;
  for (int64_t agent = 0; agent < 100; ++agent) log.Report("DREAM_CMD_0", "test", agent);
  log.Report("DREAM_CMD_0", "no sender known");
  EXPECT_EQ(log.count("DREAM_CMD_0"), 101);
  EXPECT_EQ(log.senders().at("DREAM_CMD_0"), (std::set<int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
}

}  // namespace
}  // namespace dream::testing
