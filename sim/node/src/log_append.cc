#include "dream/node/log_append.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "dream/files/regular_file.h"
#include "dream/files/temporary_file.h"
#include "dream/lcm/log_reader.h"

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

std::vector<uint8_t> EventBytes(int64_t event_number, const std::string& channel, int64_t utime, const void* data,
                                int size) {
  if (size < 0 || channel.empty() || channel.size() > 256) {
    throw std::invalid_argument("a log event needs a channel of 1-256 characters and a size >= 0");
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
  return event;
}

// Copies the first `length` bytes of the file at `path` into `into`.
void CopyHead(const std::string& path, int64_t length, files::TemporaryFile& into) {
  const files::RegularFile file(path);
  std::string chunk;
  for (int64_t at = 0; at < length;) {
    chunk.resize(static_cast<size_t>(std::min<int64_t>(length - at, 1 << 20)));
    const ssize_t n = ::pread(file.descriptor(), chunk.data(), chunk.size(), at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw std::runtime_error("cannot rewrite the run log " + path +
                               ": reading it: " + std::strerror(n < 0 ? errno : EIO));
    }
    chunk.resize(static_cast<size_t>(n));
    into.Write(chunk);
    at += n;
  }
}

}  // namespace

void AppendLogEvent(const std::string& path, int64_t event_number, const std::string& channel, int64_t utime,
                    const void* data, int size) {
  const std::vector<uint8_t> event = EventBytes(event_number, channel, utime, data, size);

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

void ReplaceLastLogEvent(const std::string& path, const std::string& channel, int64_t utime, const void* data,
                         int size) {
  int64_t last_offset = -1;
  int64_t last_index = -1;
  std::string last_channel;
  {
    lcm::LogReader reader(path);
    lcm::LogRecord record;
    while (reader.Next(&record)) {
      last_offset = reader.event_offset();
      last_index = reader.event_index();
      last_channel = std::move(record.channel);
    }
  }
  if (last_channel != channel) {
    throw std::runtime_error("cannot replace the last " + channel + " of the run log " + path + ": its last event is " +
                             (last_index < 0 ? std::string("none") : "on " + last_channel));
  }
  const std::vector<uint8_t> event = EventBytes(last_index, channel, utime, data, size);
  // The log with its last event replaced, written beside it and renamed over it:
  // a reader sees the old log or the new one, never one without the event.
  files::TemporaryFile replaced(path);
  CopyHead(path, last_offset, replaced);
  replaced.Write(std::string(event.begin(), event.end()));
  replaced.Sync();
  replaced.Commit();
}

}  // namespace dream::node
