#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace dream::lcm {

/// One event of an LCM log.
struct LogRecord {
  int64_t utime = 0;  ///< the log's timestamp, microseconds (simulated time in dream runs)
  std::string channel;
  std::vector<uint8_t> data;
};

/// Reads an LCM event log (as written by lcm-logger or a dream run) event by
/// event. A file that is not an LCM log, is cut short, or has a damaged event
/// gives a clear error naming the file and byte, never garbage or a crash.
class LogReader {
 public:
  /// The path is opened without blocking and the opened file asked what it
  /// is, so a FIFO or device given as a log is refused instead of waited on.
  /// @throws std::runtime_error naming the path when it cannot be opened, is
  ///         not a regular file or does not start like an LCM log.
  explicit LogReader(std::string path);
  ~LogReader();
  LogReader(const LogReader&) = delete;
  LogReader& operator=(const LogReader&) = delete;

  /// The next event, or false at the end of the log.
  /// @throws std::runtime_error when the file ends inside an event.
  bool Next(LogRecord* record);

  /// Where the event last returned by Next() starts in the file, and its
  /// index (from 0): for errors about its message, "at byte N".
  int64_t event_offset() const { return event_offset_; }
  int64_t event_index() const { return events_ - 1; }

  /// Every event of the file at `path`.
  static std::vector<LogRecord> ReadAll(const std::string& path);

 private:
  [[noreturn]] void Fail(const std::string& problem) const;
  bool Read(void* into, int64_t bytes);

  std::string path_;
  std::FILE* in_ = nullptr;
  int64_t file_size_ = 0;
  int64_t events_ = 0;
  int64_t bytes_read_ = 0;  // bytes of complete events so far
  int64_t event_offset_ = 0;
};

}  // namespace dream::lcm
