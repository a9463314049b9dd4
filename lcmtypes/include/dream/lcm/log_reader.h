#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lcm {
class LogFile;
}

namespace dream::lcm {

/// One event of an LCM log.
struct LogRecord {
  int64_t utime = 0;  ///< the log's timestamp, microseconds (simulated time in dream runs)
  std::string channel;
  std::vector<uint8_t> data;
};

/// Reads an LCM event log (as written by lcm-logger or a dream run) event by
/// event. A file that is not an LCM log, or is cut short, gives a clear error
/// rather than garbage.
class LogReader {
 public:
  /// @throws std::runtime_error naming the path when it cannot be opened or
  ///         does not start like an LCM log.
  explicit LogReader(std::string path);
  ~LogReader();

  /// The next event, or false at the end of the log.
  /// @throws std::runtime_error when the file ends inside an event.
  bool Next(LogRecord* record);

  /// Every event of the file at `path`.
  static std::vector<LogRecord> ReadAll(const std::string& path);

 private:
  std::string path_;
  std::unique_ptr<::lcm::LogFile> log_;
  int64_t file_size_ = 0;
  int64_t events_ = 0;
  int64_t bytes_read_ = 0;  // bytes of complete events so far
};

}  // namespace dream::lcm
