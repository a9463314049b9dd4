#include "dream/lcm/log_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "dream/lcm/big_endian.h"

namespace dream::lcm {
namespace {

// LCM event log format: per event, big-endian: uint32 sync word, int64 event
// number, int64 timestamp, int32 channel length, int32 data length, then the
// channel name and the payload. We parse it ourselves rather than through
// lcm::LogFile, whose reader trusts the lengths (a damaged header makes it
// allocate 2 GB or read into a null buffer) and silently skips garbage.
constexpr uint32_t kSyncWord = 0xEDA1DA01;
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;
// LCM itself refuses channel names longer than this.
constexpr int64_t kMaxChannelBytes = 256;

uint64_t BigEndian(const unsigned char* bytes, int count) { return BigEndianAt(bytes, static_cast<size_t>(count)); }

}  // namespace

LogReader::LogReader(std::string path) : path_(std::move(path)) {
  // As files::RegularFile does (this floor is below it): O_NONBLOCK, so a FIFO
  // is not waited on in open(), then the opened descriptor (not the path,
  // which could change in between) is asked whether it is a regular file.
  const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    throw std::runtime_error(path_ + (errno == ENOENT ? std::string(": no such log file")
                                                      : ": cannot open the log: " + std::string(std::strerror(errno))));
  }
  struct stat status {};
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(fd);
    throw std::runtime_error(path_ + ": not a regular file (a folder, FIFO or device), so no log file");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  file_size_ = static_cast<int64_t>(status.st_size);
  in_ = ::fdopen(fd, "rb");
  if (in_ == nullptr) {
    ::close(fd);
    throw std::runtime_error(path_ + ": cannot open the log: " + std::strerror(errno));
  }
  if (file_size_ > 0) {
    unsigned char head[4] = {0, 0, 0, 0};
    if (!Read(head, 4) || BigEndian(head, 4) != kSyncWord) {
      std::fclose(in_);
      throw std::runtime_error(path_ + ": not an LCM log (it does not start with the LCM event sync word)");
    }
    std::rewind(in_);
  }
}

LogReader::~LogReader() { std::fclose(in_); }

bool LogReader::Read(void* into, int64_t bytes) {
  return std::fread(into, 1, static_cast<size_t>(bytes), in_) == static_cast<size_t>(bytes);
}

void LogReader::Fail(const std::string& problem) const {
  throw std::runtime_error(path_ + ": " + problem + " at byte " + std::to_string(bytes_read_) + " (after event " +
                           std::to_string(events_) + "); the log is cut short or damaged");
}

bool LogReader::Next(LogRecord* record) {
  const int64_t remaining = file_size_ - bytes_read_;
  if (remaining == 0) return false;
  if (remaining < kEventHeaderBytes) Fail("an incomplete event header");
  unsigned char header[kEventHeaderBytes];
  if (!Read(header, kEventHeaderBytes)) Fail("a read error");
  if (BigEndian(header, 4) != kSyncWord) Fail("no LCM sync word");
  const auto channel_bytes = static_cast<int32_t>(BigEndian(header + 20, 4));
  const auto data_bytes = static_cast<int32_t>(BigEndian(header + 24, 4));
  if (channel_bytes <= 0 || channel_bytes > kMaxChannelBytes) {
    Fail("an impossible channel name length " + std::to_string(channel_bytes));
  }
  if (data_bytes < 0 || kEventHeaderBytes + channel_bytes + data_bytes > remaining) {
    Fail("a payload of " + std::to_string(data_bytes) + " bytes that does not fit in the file");
  }
  record->utime = static_cast<int64_t>(BigEndian(header + 12, 8));
  record->channel.resize(static_cast<size_t>(channel_bytes));
  record->data.resize(static_cast<size_t>(data_bytes));
  if (!Read(record->channel.data(), channel_bytes) || !Read(record->data.data(), data_bytes)) Fail("a read error");
  event_offset_ = bytes_read_;
  bytes_read_ += kEventHeaderBytes + channel_bytes + data_bytes;
  ++events_;
  return true;
}

std::vector<LogRecord> LogReader::ReadAll(const std::string& path) {
  LogReader reader(path);
  std::vector<LogRecord> records;
  LogRecord record;
  while (reader.Next(&record)) records.push_back(record);
  return records;
}

}  // namespace dream::lcm
