#include "dream/lcm/channel_prefix_filter.h"

#include <sys/socket.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <set>

namespace dream::lcm {

namespace {

// LCM's short (unfragmented) datagram: "LC02", a sequence number, then the
// channel name, NUL-terminated. The filter sees a UDP socket's datagram from
// its UDP header (8 bytes) on.
constexpr uint32_t kUdpHeaderBytes = 8;
constexpr uint32_t kShortMagic = 0x4c433032;  // "LC02"
constexpr uint32_t kChannelOffset = kUdpHeaderBytes + 8;
constexpr uint32_t kPass = 0xffffffffu;  // keep the whole datagram
constexpr uint32_t kDrop = 0;

bool IsRegexSpecial(char c) { return std::strchr(".[]()*+?{}|^$\\", c) != nullptr; }

bool IsQuantifier(char c) { return c == '*' || c == '+' || c == '?' || c == '{'; }

// A big-endian word, half-word or byte of `text` at `at`, as BPF's absolute loads read them.
uint32_t BigEndian(const std::string& text, size_t at, size_t bytes) {
  uint32_t value = 0;
  for (size_t i = 0; i < bytes; ++i) value = (value << 8) | static_cast<unsigned char>(text[at + i]);
  return value;
}

uint16_t LoadSize(size_t bytes) { return bytes == 4 ? BPF_W : bytes == 2 ? BPF_H : BPF_B; }

// Instructions checking that the channel starts with `prefix`; `fail` jumps
// (relative, filled in later) go past the block.
std::vector<sock_filter> PrefixBlock(const std::string& prefix) {
  std::vector<sock_filter> block;
  // Too short to hold the prefix: an out-of-bounds load would end the whole
  // program with a drop, before the other prefixes were tried.
  block.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_LEN, 0));
  block.push_back(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, kChannelOffset + static_cast<uint32_t>(prefix.size()), 0, 0));
  for (size_t at = 0; at < prefix.size();) {
    const size_t left = prefix.size() - at;
    const size_t bytes = left >= 4 ? 4 : left >= 2 ? 2 : 1;
    block.push_back(BPF_STMT(BPF_LD | LoadSize(bytes) | BPF_ABS, kChannelOffset + static_cast<uint32_t>(at)));
    block.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, BigEndian(prefix, at, bytes), 0, 0));
    at += bytes;
  }
  block.push_back(BPF_STMT(BPF_RET | BPF_K, kPass));
  // Every conditional jump's false branch leaves the block.
  for (size_t i = 0; i < block.size(); ++i) {
    if (BPF_CLASS(block[i].code) == BPF_JMP) block[i].jf = static_cast<uint8_t>(block.size() - i - 1);
  }
  return block;
}

}  // namespace

std::string ChannelPrefixFilter::LiteralPrefix(const std::string& regex) {
  // An alternative anywhere may start with anything.
  if (regex.find('|') != std::string::npos) return "";
  std::string prefix;
  for (const char c : regex) {
    if (IsRegexSpecial(c)) {
      // "AB?" or "AB*" may lack the B.
      if (IsQuantifier(c) && !prefix.empty()) prefix.pop_back();
      break;
    }
    prefix += c;
  }
  return prefix;
}

ChannelPrefixFilter::ChannelPrefixFilter(const std::vector<std::string>& prefixes) {
  std::set<std::string> distinct;
  for (const std::string& prefix : prefixes) {
    if (prefix.empty()) return;  // some subscriber may want any channel
    distinct.insert(prefix.substr(0, kMaxPrefixBytes));
  }
  if (distinct.empty() || distinct.size() > kMaxPrefixes) return;
  program_.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, kUdpHeaderBytes));  // too short for a magic: LCM drops it too
  program_.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kShortMagic, 1, 0));
  program_.push_back(BPF_STMT(BPF_RET | BPF_K, kPass));  // a fragment or not LCM's: LCM decides
  for (const std::string& prefix : distinct) {
    const std::vector<sock_filter> block = PrefixBlock(prefix);
    program_.insert(program_.end(), block.begin(), block.end());
  }
  program_.push_back(BPF_STMT(BPF_RET | BPF_K, kDrop));
}

bool ChannelPrefixFilter::ApplyTo(int fd) const {
  if (passes_everything()) {
    RemoveFrom(fd);
    return true;
  }
  sock_fprog fprog{};
  fprog.len = static_cast<unsigned short>(program_.size());
  fprog.filter = const_cast<sock_filter*>(program_.data());  // the kernel copies it
  return setsockopt(fd, SOL_SOCKET, SO_ATTACH_FILTER, &fprog, sizeof(fprog)) == 0;
}

void ChannelPrefixFilter::RemoveFrom(int fd) {
  int unused = 0;
  // ENOENT when there was none: nothing to take off.
  (void)setsockopt(fd, SOL_SOCKET, SO_DETACH_FILTER, &unused, sizeof(unused));
}

}  // namespace dream::lcm
