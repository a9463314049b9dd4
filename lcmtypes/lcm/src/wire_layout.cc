#include "dream/lcm/wire_layout.h"

#include <cstring>
#include <stdexcept>

#include "dream/lcm/wire_text.h"

namespace dream::lcm {
namespace {

constexpr int64_t kFingerprintBytes = 8;

int64_t BigEndian(const uint8_t* bytes, int count) {
  uint64_t value = 0;
  for (int i = 0; i < count; ++i) value = (value << 8) | bytes[i];
  return static_cast<int64_t>(value);
}

// Why `count` LCM booleans from byte `at` are not all 0 or 1, or nothing.
std::optional<std::string> NotBooleans(const uint8_t* bytes, int64_t at, int64_t count) {
  for (int64_t i = at; i < at + count; ++i) {
    if (bytes[i] > 1)
      return "boolean at byte " + std::to_string(i) + " is " + std::to_string(bytes[i]) + ", not 0 or 1";
  }
  return std::nullopt;
}

}  // namespace

WireLayout& WireLayout::Fixed(int bytes) {
  fields_.push_back({Kind::kFixed, bytes});
  return *this;
}

WireLayout& WireLayout::AgentId() {
  fields_.push_back({Kind::kAgentId, 8});
  return *this;
}

WireLayout& WireLayout::Boolean() {
  fields_.push_back({Kind::kBoolean, 1});
  return *this;
}

WireLayout& WireLayout::Count(int32_t max) {
  fields_.push_back({Kind::kCount, max});
  return *this;
}

WireLayout& WireLayout::Array(int element_bytes) {
  bool counted = false;
  for (const Field& field : fields_) counted = counted || field.kind == Kind::kCount;
  if (!counted) throw std::logic_error("WireLayout: an Array needs a Count before it");
  fields_.push_back({Kind::kArray, element_bytes});
  return *this;
}

WireLayout& WireLayout::BooleanArray() {
  Array(1);
  fields_.back().kind = Kind::kBooleanArray;
  return *this;
}

WireLayout& WireLayout::String(int32_t max_bytes) {
  fields_.push_back({Kind::kString, max_bytes});
  return *this;
}

std::optional<std::string> WireLayout::Problem(const void* data, int size) const {
  const auto* bytes = static_cast<const uint8_t*>(data);
  if (size < 0 || (size > 0 && data == nullptr)) return "no bytes";
  // All arithmetic in int64: counts are at most int32, sizes at most int32,
  // and a product of the two is checked against the bytes left, never summed first.
  int64_t at = 0;
  const auto left = [&] { return static_cast<int64_t>(size) - at; };
  const auto cut = [&](const char* what) {
    return std::string("cut short in ") + what + " at byte " + std::to_string(at) + " of " + std::to_string(size);
  };
  if (left() < kFingerprintBytes) return cut("the fingerprint");
  if (BigEndian(bytes, kFingerprintBytes) != fingerprint_) return std::string("a different type (fingerprint)");
  at += kFingerprintBytes;
  int64_t count = 0;
  for (const Field& field : fields_) {
    switch (field.kind) {
      case Kind::kFixed:
      case Kind::kAgentId:
        if (left() < field.bytes_or_max) return cut("fixed fields");
        at += field.bytes_or_max;
        break;
      case Kind::kBoolean:
        if (left() < 1) return cut("a boolean");
        if (std::optional<std::string> problem = NotBooleans(bytes, at, 1)) return problem;
        ++at;
        break;
      case Kind::kCount:
        if (left() < 4) return cut("a count");
        count = static_cast<int32_t>(BigEndian(bytes + at, 4));
        if (count < 0 || count > field.bytes_or_max) {
          return "count " + std::to_string(count) + " at byte " + std::to_string(at) + " is outside 0.." +
                 std::to_string(field.bytes_or_max);
        }
        at += 4;
        break;
      case Kind::kArray:
        if (count * field.bytes_or_max > left()) {
          return "count " + std::to_string(count) + " needs " + std::to_string(count * field.bytes_or_max) +
                 " bytes at byte " + std::to_string(at) + ", only " + std::to_string(left()) + " left";
        }
        at += count * field.bytes_or_max;
        break;
      case Kind::kBooleanArray:
        if (count > left()) return cut("a boolean array");
        if (std::optional<std::string> problem = NotBooleans(bytes, at, count)) return problem;
        at += count;
        break;
      case Kind::kString: {
        if (left() < 4) return cut("a string length");
        const int64_t length = static_cast<int32_t>(BigEndian(bytes + at, 4));
        if (length < 1 || length > field.bytes_or_max + 1) {
          return "string length " + std::to_string(length) + " at byte " + std::to_string(at) + " is outside 1.." +
                 std::to_string(field.bytes_or_max + 1);
        }
        at += 4;
        if (length > left()) return cut("a string");
        // lcm-gen's decoder drops the last byte unseen and its encoder stops at
        // the first NUL: only text ending in its one NUL survives both, and
        // only UTF-8 text can go into summary.json and dream log's JSON.
        const auto* text = bytes + at;
        const auto* nul = static_cast<const uint8_t*>(std::memchr(text, 0, static_cast<size_t>(length)));
        if (nul != text + length - 1) {
          return "string at byte " + std::to_string(at) +
                 (nul == nullptr ? " does not end in a NUL" : " holds a NUL before its end");
        }
        const int64_t bad = WireText::FirstNonUtf8Byte(text, length - 1);
        if (bad >= 0) {
          return "string at byte " + std::to_string(at) + " is not UTF-8 text (byte " + std::to_string(at + bad) +
                 " is " + std::to_string(text[bad]) + ")";
        }
        at += length;
        break;
      }
    }
  }
  if (left() != 0) return std::to_string(left()) + " trailing bytes after a complete message of " + std::to_string(at);
  return std::nullopt;
}

std::optional<int64_t> WireLayout::AgentIdOf(const void* data, int size) const {
  int64_t at = kFingerprintBytes;
  for (const Field& field : fields_) {
    if (field.kind == Kind::kAgentId) {
      if (data == nullptr || at + 8 > size) return std::nullopt;
      return BigEndian(static_cast<const uint8_t*>(data) + at, 8);
    }
    if (field.kind != Kind::kFixed) return std::nullopt;  // further fields move with the counts
    at += field.bytes_or_max;
  }
  return std::nullopt;
}

int64_t WireLayout::MinimumBytes() const {
  int64_t bytes = kFingerprintBytes;
  for (const Field& field : fields_) {
    if (field.kind == Kind::kFixed || field.kind == Kind::kAgentId || field.kind == Kind::kBoolean) {
      bytes += field.bytes_or_max;
    }
    if (field.kind == Kind::kCount || field.kind == Kind::kString) bytes += 4;
    if (field.kind == Kind::kString) bytes += 1;  // the NUL of an empty string
  }
  return bytes;
}

}  // namespace dream::lcm
