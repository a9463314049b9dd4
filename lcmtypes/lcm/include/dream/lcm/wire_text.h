#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace dream::lcm {

/// What an LCM string field must hold to be accepted (WireLayout::String):
/// UTF-8 text without NUL. lcm-gen's encoder stops at the first NUL, and
/// summary.json and dream log's JSON cannot carry bytes that are not UTF-8.
class WireText {
 public:
  /// Where `bytes` stop being UTF-8 text (RFC 3629: no overlong forms, no
  /// surrogates, nothing past U+10FFFF), or -1 when they are text throughout.
  static int64_t FirstNonUtf8Byte(const uint8_t* bytes, int64_t size);

  /// `text` made acceptable: each byte that is not UTF-8 becomes '?', each NUL
  /// "\0", and the result is cut to at most `max_bytes` between characters.
  /// For the texts we send that hold what we did not write (file paths, URLs,
  /// a controller's error).
  static std::string Of(const std::string& text, size_t max_bytes);
};

}  // namespace dream::lcm
