#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace dream::lcm {

/// The header every dream message starts with on the wire (lcmtypes/dream/*.lcm):
/// the 8-byte lcm-gen fingerprint, then int64 utime, int64 step, int64 run_id,
/// all big-endian. Commands, radio and faults go on with an int32 robot id
/// (robot_id / sender_id), commands and radio with an int64 agent_id. Written
/// once here so a relay that forwards bytes without decoding them (the Python
/// host's) reads them as lcm-gen wrote them; tests/lcm checks the offsets
/// against lcm-gen's own encoding.
class MessageHeader {
 public:
  static constexpr size_t kFingerprintAt = 0;
  static constexpr size_t kUtimeAt = 8;
  static constexpr size_t kStepAt = 16;
  static constexpr size_t kRunIdAt = 24;
  /// Bytes of the common header: what a message must hold for Read() to say anything.
  static constexpr size_t kBytes = 32;
  /// velocity_command_t, radio_message_t, robot_fault_t: the robot it is of.
  static constexpr size_t kRobotIdAt = 32;
  /// velocity_command_t and radio_message_t: the sending agent.
  static constexpr size_t kAgentIdAt = 36;

  int64_t fingerprint = 0;
  int64_t utime = 0;
  int64_t step = 0;
  int64_t run_id = 0;

  /// The header of `size` bytes at `data`, or nothing when they are fewer than kBytes.
  /// Only the header is read: whether the rest decodes is lcm::Decode's to say.
  static std::optional<MessageHeader> Read(const void* data, size_t size);
  /// The agent_id of a command or radio message, or nothing when the bytes do not reach it.
  static std::optional<int64_t> AgentIdOf(const void* data, size_t size);

  /// The big-endian int64 at byte `at` (the caller checked `at + 8 <= size`).
  static int64_t Int64At(const void* data, size_t at);
};

}  // namespace dream::lcm
