#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dream::lcm {

/// The shape of one LCM message type on the wire: its 8-byte fingerprint,
/// then fields in order. Check() walks bytes along it, reading only the
/// counts and lengths, so a message can be refused before the lcm-gen
/// decoder runs. That decoder resizes its vectors from the count before it
/// looks at the bytes, and sums sizes in an int that overflows, so a forged
/// count makes it allocate gigabytes or write past the buffer.
class WireLayout {
 public:
  explicit WireLayout(int64_t fingerprint) : fingerprint_(fingerprint) {}

  /// `bytes` of scalar fields.
  WireLayout& Fixed(int bytes);
  /// An int64 naming the sending agent (the message's agent_id), reported
  /// with a bad message when the bytes reach that far.
  WireLayout& AgentId();
  /// An LCM boolean: one byte, 0 or 1 (lcm-gen would read 2 as true and
  /// write it back as 1).
  WireLayout& Boolean();
  /// An int32 element count that must be in 0..max; the Array()s after it use it.
  WireLayout& Count(int32_t max);
  /// Elements of `element_bytes` each, as many as the latest Count() says.
  WireLayout& Array(int element_bytes);
  /// LCM booleans, as many as the latest Count() says: each 0 or 1.
  WireLayout& BooleanArray();
  /// An LCM string: int32 length (with its NUL, so >= 1) then that many
  /// bytes: UTF-8 text with no NUL but the last.
  WireLayout& String(int32_t max_bytes);

  /// What is wrong with `size` bytes at `data` as one message of this type
  /// (wrong fingerprint, a count over its limit or over the bytes left,
  /// truncated, trailing bytes), or nothing when they hold exactly one.
  std::optional<std::string> Problem(const void* data, int size) const;

  /// The agent_id field of a message of this type, if it has one and the
  /// bytes reach it; it names the sender even when the rest is bad.
  std::optional<int64_t> AgentIdOf(const void* data, int size) const;

  /// Bytes of a message whose counts are all zero and strings empty: the
  /// lcm-gen encoded size of a default message (tests compare the two).
  int64_t MinimumBytes() const;

 private:
  enum class Kind { kFixed, kAgentId, kBoolean, kCount, kArray, kBooleanArray, kString };
  struct Field {
    Kind kind;
    int64_t bytes_or_max;
  };

  int64_t fingerprint_;
  std::vector<Field> fields_;
};

}  // namespace dream::lcm
