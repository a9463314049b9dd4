#include "dream/python_host/relay_link.h"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "dream/lcm/big_endian.h"

namespace dream::python_host {
namespace {

constexpr size_t kHeaderBytes = 9;

void PutUint32(uint32_t value, std::string* out) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<char>((value >> shift) & 0xff));
}

uint32_t GetUint32(const char* bytes) { return static_cast<uint32_t>(lcm::BigEndianAt(bytes, 4)); }

}  // namespace

RelayLink::RelayLink(int fd) : fd_(fd) {}

RelayLink::~RelayLink() {
  if (fd_ >= 0) ::close(fd_);
}

void RelayLink::Encode(char kind, const std::string& channel, const void* data, size_t size, std::string* out) {
  out->push_back(kind);
  PutUint32(static_cast<uint32_t>(channel.size()), out);
  PutUint32(static_cast<uint32_t>(size), out);
  out->append(channel);
  out->append(static_cast<const char*>(data), size);
}

bool RelayLink::Send(char kind, const std::string& channel, const void* data, size_t size) {
  if (channel.size() > kMaxChannelBytes || size > kMaxDataBytes) return false;
  std::string frame;
  Encode(kind, channel, data, size, &frame);
  const std::lock_guard<std::mutex> lock(send_mutex_);
  size_t sent = 0;
  while (sent < frame.size()) {
    const ssize_t n = ::send(fd_, frame.data() + sent, frame.size() - sent, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    sent += static_cast<size_t>(n);
  }
  return true;
}

int RelayLink::TakeFrame(Frame* frame, std::string* problem) {
  if (buffer_.size() < kHeaderBytes) return 0;
  const uint32_t channel_bytes = GetUint32(buffer_.data() + 1);
  const uint32_t data_bytes = GetUint32(buffer_.data() + 5);
  if (channel_bytes > kMaxChannelBytes || data_bytes > kMaxDataBytes) {
    *problem = "a frame of " + std::to_string(channel_bytes) + " + " + std::to_string(data_bytes) +
               " bytes, beyond the bounds (" + std::to_string(kMaxChannelBytes) + " + " +
               std::to_string(kMaxDataBytes) + ")";
    return -1;
  }
  const size_t total = kHeaderBytes + channel_bytes + data_bytes;
  if (buffer_.size() < total) return 0;
  frame->kind = buffer_[0];
  frame->channel.assign(buffer_, kHeaderBytes, channel_bytes);
  frame->data.assign(buffer_, kHeaderBytes + channel_bytes, data_bytes);
  buffer_.erase(0, total);
  return 1;
}

bool RelayLink::Receive(Frame* frame) {
  std::string problem;
  char chunk[65536];
  while (true) {
    const int taken = TakeFrame(frame, &problem);
    if (taken > 0) return true;
    if (taken < 0) throw std::runtime_error("relay: " + problem);
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    buffer_.append(chunk, static_cast<size_t>(n));
  }
}

RelayLink::Read RelayLink::ReadAvailable(std::vector<Frame>* frames, std::string* problem) {
  char chunk[65536];
  bool closed = false;
  // Bounded per call, so one flood cannot hold the caller.
  for (int reads = 0; reads < 64; ++reads) {
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    if (n <= 0) {
      closed = true;
      break;
    }
    buffer_.append(chunk, static_cast<size_t>(n));
    Frame frame;
    int taken = 0;
    while ((taken = TakeFrame(&frame, problem)) > 0) frames->push_back(std::move(frame));
    if (taken < 0) return Read::kMalformed;
  }
  return closed ? Read::kClosed : Read::kOpen;
}

void RelayLink::Shutdown() { ::shutdown(fd_, SHUT_RDWR); }

}  // namespace dream::python_host
