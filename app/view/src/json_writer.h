#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace dream::view {

/// Appends compact JSON to a string: the view's frames are written many
/// times a second, with fixed precision (a tree of nlohmann::json values and
/// 17-digit doubles would cost more and weigh three times as much).
/// Commas are placed by the writer; keys and values are the caller's order.
class JsonWriter {
 public:
  explicit JsonWriter(std::string* out) : out_(out) {}

  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  /// "key": (inside an object; the value follows).
  JsonWriter& Key(std::string_view key);
  /// A number with `decimals` digits after the point (trailing zeros kept
  /// short); null when it is not finite.
  JsonWriter& Number(double value, int decimals);
  /// A number with `digits` significant digits (metrics: 1e-5 and 20000 alike); null when not finite.
  JsonWriter& Significant(double value, int digits);
  JsonWriter& Integer(int64_t value);
  JsonWriter& Bool(bool value);
  JsonWriter& Null();
  /// A string, escaped (quotes, backslashes, control characters); bytes that
  /// are not valid UTF-8 become U+FFFD, so any text from the bus can be sent.
  JsonWriter& String(std::string_view text);

 private:
  void Separate();
  void AppendQuoted(std::string_view text);

  std::string* out_;
  bool first_ = true;       // no value yet in the current container
  bool after_key_ = false;  // a key was written: the value takes no comma
};

}  // namespace dream::view
