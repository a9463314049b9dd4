#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lcm {
class LogFile;
}

namespace dream::node {

/// Writes a run as a standard LCM event log (the format lcm-logger writes and
/// lcm-logplayer replays), with timestamps in simulated time.
///
/// The log is written to "<path>.part" and renamed to <path> by Close(), so a
/// file at <path> only ever holds whole events. Events are flushed to the
/// kernel at least every `flush_interval_events`, so even a killed run leaves
/// a readable .part file.
///
/// When the disk refuses an event (full disk, file size limit, I/O error) the
/// recorder cuts the file back to the end of its last whole event, so the log
/// stays a valid LCM log holding every event that fitted before the failure,
/// and becomes failed: the failing call throws, and so does every later Write,
/// without writing anything. Close() still gives that log its final name: it
/// is the run's data, and failure() says why it ends early.
class RunRecorder {
 public:
  /// @throws std::runtime_error naming the path when it cannot be created.
  explicit RunRecorder(std::string path, int flush_interval_events = 256);
  ~RunRecorder();  // Closes if still open; never throws.

  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  /// Appends one event. @param utime simulated time, microseconds.
  /// @throws std::runtime_error with failure() when the event cannot be written
  /// (the log is cut back to its last whole event) or the recorder has failed
  /// before; std::logic_error after Close().
  void Write(const std::string& channel, int64_t utime, const void* data, int size);

  /// What the log keeps in place of an event on a rewritten channel.
  using Rewrite = std::function<void(int64_t utime, const void* data, int size)>;
  /// From now on Write hands each event on `channel` to `rewrite` instead of
  /// writing it; `rewrite` writes (with Write, on any channel, its own events
  /// are not handed back) what the log keeps instead. A run with
  /// world.realism keeps the true poses on DREAM_POSES and what the agents
  /// were sent on DREAM_MEASURED_POSES (TruePoseRecording, for RunSession).
  void RewriteChannel(std::string channel, Rewrite rewrite);

  /// Pushes every event written so far to the disk (fflush + fsync), so a
  /// full disk shows now rather than at Close(). Fails like Write.
  void Flush();

  /// Flushes, syncs and renames the .part file to the final path; a failed
  /// recorder's log (every whole event before the failure) is renamed too.
  /// Only the file this recorder created is renamed: when <path>.part is no
  /// longer it (the folder removed and made again by another run), nothing
  /// is renamed and Close throws.
  /// Idempotent. @throws std::runtime_error when flushing fails here (the log
  /// is still cut back and renamed), or when the log cannot get its final
  /// name (it then stays at <path>.part).
  void Close();

  const std::string& path() const { return path_; }
  /// Whole events in the log; after a failure, the ones it kept.
  int64_t events_written() const { return events_written_; }
  bool failed() const { return !failure_.empty(); }
  /// Why writing failed, in one line naming the file and the OS error, and
  /// how many whole events the log kept; empty while nothing failed.
  const std::string& failure() const { return failure_; }
  /// True once Close() found <path>.part no longer the file this recorder
  /// wrote (its folder removed and made again): what the folder holds now is
  /// another run's, and nothing of this run may be written over it.
  bool part_replaced() const { return part_replaced_; }

 private:
  /// Cuts the file back to its last whole event on disk, records why in
  /// failure_ and throws it. @param action what failed ("writing", ...).
  [[noreturn]] void Fail(const std::string& action, int error_number);
  /// True while part_path_ names the file this recorder opened (device and inode).
  bool PartPathHoldsThisLog() const;

  std::string path_;
  std::string part_path_;
  std::unique_ptr<::lcm::LogFile> log_;
  int flush_interval_events_;
  int64_t events_written_ = 0;
  int64_t bytes_written_ = 0;  // end of the last whole event handed to stdio
  // Up to here the file is known to hold whole events on disk (last good fflush).
  int64_t events_flushed_ = 0;
  int64_t bytes_flushed_ = 0;
  // File offset just past each event written since the last good fflush: stdio
  // may have pushed any prefix of them to the disk before a failure.
  std::vector<int64_t> unflushed_event_ends_;
  std::string failure_;
  std::string rewritten_channel_;
  Rewrite rewrite_;
  bool rewriting_ = false;        // inside rewrite_: its writes go to the log
  bool cut_back_failed_ = false;  // the .part may end mid-event: never renamed
  uint64_t part_device_ = 0;      // the .part file opened, to rename it by what it is
  uint64_t part_inode_ = 0;
  bool part_replaced_ = false;
};

}  // namespace dream::node
