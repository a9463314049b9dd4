#include "dream/node/log_append.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace dream::node {
namespace {

// An LCM log event: magic, event number, timestamp, channel length, data
// length (big-endian: 4 + 8 + 8 + 4 + 4 bytes), then channel and data.
constexpr uint32_t kEventMagic = 0xEDA1DA01;

void PutBigEndian(std::vector<uint8_t>* bytes, uint64_t value, int width) {
  for (int shift = 8 * (width - 1); shift >= 0; shift -= 8) bytes->push_back(static_cast<uint8_t>(value >> shift));
}

std::runtime_error Failure(const std::string& path, const std::string& action, int error_number) {
  return std::runtime_error("cannot append to the run log " + path + ": " + action + ": " +
                            (error_number != 0 ? std::strerror(error_number) : "unknown error"));
}

}  // namespace

void AppendLogEvent(const std::string& path, int64_t event_number, const std::string& channel, int64_t utime,
                    const void* data, int size) {
  if (size < 0 || channel.empty() || channel.size() > 256) {
    throw std::invalid_argument("AppendLogEvent: a channel of 1-256 characters and a size >= 0");
  }
  std::vector<uint8_t> event;
  event.reserve(28 + channel.size() + static_cast<size_t>(size));
  PutBigEndian(&event, kEventMagic, 4);
  PutBigEndian(&event, static_cast<uint64_t>(event_number), 8);
  PutBigEndian(&event, static_cast<uint64_t>(utime), 8);
  PutBigEndian(&event, channel.size(), 4);
  PutBigEndian(&event, static_cast<uint64_t>(size), 4);
  event.insert(event.end(), channel.begin(), channel.end());
  const auto* bytes = static_cast<const uint8_t*>(data);
  event.insert(event.end(), bytes, bytes + size);

  // No O_CREAT: only a log that exists gets the event; O_NOFOLLOW: never through a link.
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) throw Failure(path, "opening it", errno);
  struct stat status {};
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    const int error = errno;
    ::close(fd);
    throw Failure(path, "it is no regular file", error);
  }
  size_t written = 0;
  int error = 0;
  while (written < event.size()) {
    const ssize_t n = ::write(fd, event.data() + written, event.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : ENOSPC;
      break;
    }
    written += static_cast<size_t>(n);
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (error != 0) {
    // The part of the event that made it is cut off: the log keeps whole events only.
    (void)!::ftruncate(fd, status.st_size);
    ::close(fd);
    throw Failure(path, "writing " + channel, error);
  }
  ::close(fd);
}

}  // namespace dream::node
