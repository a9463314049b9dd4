#include "dream/lcm/wire_text.h"

namespace dream::lcm {

int64_t WireText::FirstNonUtf8Byte(const uint8_t* bytes, int64_t size) {
  int64_t i = 0;
  while (i < size) {
    const uint8_t lead = bytes[i];
    int64_t extra = 0;
    uint8_t low = 0x80;
    uint8_t high = 0xBF;  // the allowed range of the first continuation byte
    if (lead < 0x80) {
      ++i;
      continue;
    } else if (lead >= 0xC2 && lead <= 0xDF) {
      extra = 1;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      extra = 2;
      if (lead == 0xE0) low = 0xA0;
      if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      extra = 3;
      if (lead == 0xF0) low = 0x90;
      if (lead == 0xF4) high = 0x8F;
    } else {
      return i;
    }
    if (size - i <= extra) return i;
    if (bytes[i + 1] < low || bytes[i + 1] > high) return i;
    for (int64_t k = 2; k <= extra; ++k) {
      if ((bytes[i + k] & 0xC0) != 0x80) return i;
    }
    i += extra + 1;
  }
  return -1;
}

std::string WireText::Of(const std::string& text, size_t max_bytes) {
  const auto* bytes = reinterpret_cast<const uint8_t*>(text.data());
  const auto size = static_cast<int64_t>(text.size());
  // The common case (SimNode's "running" every step): already acceptable.
  if (text.size() <= max_bytes && text.find('\0') == std::string::npos && FirstNonUtf8Byte(bytes, size) < 0) {
    return text;
  }
  std::string out;
  int64_t at = 0;
  while (at < size) {
    const int64_t bad = FirstNonUtf8Byte(bytes + at, size - at);
    const int64_t good_end = bad < 0 ? size : at + bad;
    for (; at < good_end; ++at) {
      if (text[static_cast<size_t>(at)] == '\0') {
        out += "\\0";
      } else {
        out += text[static_cast<size_t>(at)];
      }
    }
    if (at < size) {
      out += '?';
      ++at;
    }
  }
  if (out.size() <= max_bytes) return out;
  // Cut before a continuation byte's character, so the cut leaves whole characters.
  size_t cut = max_bytes;
  while (cut > 0 && (static_cast<uint8_t>(out[cut]) & 0xC0) == 0x80) --cut;
  out.resize(cut);
  return out;
}

}  // namespace dream::lcm
