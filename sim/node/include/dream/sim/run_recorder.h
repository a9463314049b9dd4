#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace lcm {
class LogFile;
}

namespace dream::sim {

/// Writes a run as a standard LCM event log (the format lcm-logger writes and
/// lcm-logplayer replays), with timestamps in simulated time.
///
/// The log is written to "<path>.part" and renamed to <path> by Close(), so a
/// file at <path> is always complete. Events are flushed to the kernel at
/// least every `flush_interval_events`, so even a killed run leaves a readable
/// .part file.
class RunRecorder {
 public:
  /// @throws std::runtime_error naming the path when it cannot be created.
  explicit RunRecorder(std::string path, int flush_interval_events = 256);
  ~RunRecorder();  // Closes if still open.

  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  /// Appends one event. @param utime simulated time, microseconds.
  void Write(const std::string& channel, int64_t utime, const void* data, int size);

  /// Flushes, syncs to disk and renames the .part file to the final path.
  /// Idempotent. @throws std::runtime_error on I/O failure.
  void Close();

  const std::string& path() const { return path_; }
  int64_t events_written() const { return events_written_; }

 private:
  std::string path_;
  std::string part_path_;
  std::unique_ptr<::lcm::LogFile> log_;
  int flush_interval_events_;
  int64_t events_written_ = 0;
};

}  // namespace dream::sim
