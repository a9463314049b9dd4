#include "json_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace dream::view {

void JsonWriter::Separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_) out_->push_back(',');
  first_ = false;
}

JsonWriter& JsonWriter::BeginObject() {
  Separate();
  out_->push_back('{');
  first_ = true;
  return *this;
}

JsonWriter& JsonWriter::EndObject() {
  out_->push_back('}');
  first_ = false;
  return *this;
}

JsonWriter& JsonWriter::BeginArray() {
  Separate();
  out_->push_back('[');
  first_ = true;
  return *this;
}

JsonWriter& JsonWriter::EndArray() {
  out_->push_back(']');
  first_ = false;
  return *this;
}

JsonWriter& JsonWriter::Key(std::string_view key) {
  Separate();
  AppendQuoted(key);
  out_->push_back(':');
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::Significant(double value, int digits) {
  Separate();
  char buffer[64];
  const auto [end, error] =
      std::isfinite(value) ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits)
                           : std::to_chars_result{buffer, std::errc::value_too_large};
  out_->append(error == std::errc() ? std::string_view(buffer, static_cast<size_t>(end - buffer)) : "null");
  return *this;
}

JsonWriter& JsonWriter::Number(double value, int decimals) {
  Separate();
  if (!std::isfinite(value)) {
    out_->append("null");
    return *this;
  }
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  if (error != std::errc()) {
    out_->append("null");  // beyond 64 characters: no position the page could draw
    return *this;
  }
  // 1.5000 -> 1.5, 2.0000 -> 2: a third fewer bytes in a frame.
  const char* last = end;
  if (decimals > 0) {
    while (last[-1] == '0') --last;
    if (last[-1] == '.') --last;
  }
  std::string_view text(buffer, static_cast<size_t>(last - buffer));
  if (text == "-0") text = "0";
  out_->append(text);
  return *this;
}

JsonWriter& JsonWriter::Integer(int64_t value) {
  Separate();
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out_->append(buffer, result.ptr);
  return *this;
}

JsonWriter& JsonWriter::Bool(bool value) {
  Separate();
  out_->append(value ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::Null() {
  Separate();
  out_->append("null");
  return *this;
}

JsonWriter& JsonWriter::String(std::string_view text) {
  Separate();
  AppendQuoted(text);
  return *this;
}

namespace {

/// The length of the valid UTF-8 sequence at `text[i]` (a lead byte >= 0x80),
/// or 0 when it is not one (as a browser's fatal UTF-8 decoder decides:
/// no overlong forms, no surrogates, nothing past U+10FFFF).
size_t Utf8SequenceLength(std::string_view text, size_t i) {
  const auto at = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = at(i);
  size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size() || at(i + 1) < low || at(i + 1) > high) return 0;
  for (size_t k = 2; k < length; ++k) {
    if (at(i + k) < 0x80 || at(i + k) > 0xBF) return 0;
  }
  return length;
}

}  // namespace

void JsonWriter::AppendQuoted(std::string_view text) {
  out_->push_back('"');
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"') {
      out_->append("\\\"");
    } else if (c == '\\') {
      out_->append("\\\\");
    } else if (byte < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", byte);
      out_->append(escaped);
    } else if (byte < 0x80) {
      out_->push_back(c);
    } else if (const size_t length = Utf8SequenceLength(text, i)) {
      out_->append(text.substr(i, length));
      i += length - 1;
    } else {
      // A WebSocket text message must be valid UTF-8: a browser drops the
      // connection otherwise, so a forged detail could blind every page.
      out_->append("\\ufffd");
    }
  }
  out_->push_back('"');
}

}  // namespace dream::view
