#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace dream::run_log {

/// The events of an LCM log counted per channel, and the log time they span:
/// what `dream log info` prints.
class LogChannelCounts {
 public:
  struct Channel {
    long events = 0;
    long bytes = 0;  ///< of the events' payloads
  };

  /// Reads the log file at `path`.
  /// @throws std::runtime_error for a missing, damaged or empty log (naming it).
  static LogChannelCounts Read(const std::string& path);

  /// The log file read.
  const std::string& path() const { return path_; }
  long events() const { return events_; }
  /// Log time from the first event to the last, in seconds.
  double seconds() const { return static_cast<double>(last_utime_ - first_utime_) / 1e6; }
  /// Every channel of the log, by name.
  const std::map<std::string, Channel>& channels() const { return channels_; }

 private:
  std::string path_;
  long events_ = 0;
  int64_t first_utime_ = 0;
  int64_t last_utime_ = 0;
  std::map<std::string, Channel> channels_;
};

}  // namespace dream::run_log
