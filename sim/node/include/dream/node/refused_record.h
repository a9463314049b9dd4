#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace dream::node {

class RunRecorder;

/// The messages a run heard and refused, kept apart from its log (run.lcmlog
/// holds only what the run used): per channel how many and from which step,
/// and the first of them, as heard, in an LCM log of their own
/// (refused.lcmlog) for a look with `dream log echo`.
///
/// Bounded whatever arrives: at most kMaxChannels channels are named (the
/// rest are counted together under kOtherChannels), and the log keeps at most
/// kMaxEvents events and kMaxBytes bytes of data (later messages are only
/// counted). The log is created at the first refused message, so a run that
/// refused nothing leaves none.
class RefusedRecord {
 public:
  static constexpr size_t kMaxChannels = 256;
  static constexpr const char* kOtherChannels = "(other channels)";
  static constexpr int64_t kMaxEvents = 1000;
  static constexpr int64_t kMaxBytes = int64_t{4} << 20;

  struct Channel {
    long count = 0;
    int64_t first_step = 0;  ///< the world's step when the first was heard
  };

  /// @param path where the log of refused messages goes (written as <path>.part, renamed by Close()).
  explicit RefusedRecord(std::string path);
  ~RefusedRecord();  // closes; never throws

  RefusedRecord(const RefusedRecord&) = delete;
  RefusedRecord& operator=(const RefusedRecord&) = delete;

  /// Counts one refused message heard at `step` (simulated time `utime`) and
  /// logs it while the bounds allow. Never throws: a log that cannot be
  /// written stops logging (failure() says why), the counting goes on.
  void Add(const std::string& channel, int64_t step, int64_t utime, const void* data, int size);

  /// Gives the log its final name, if one was started. Never throws.
  void Close();

  const std::map<std::string, Channel>& per_channel() const { return per_channel_; }
  long total() const { return total_; }
  const std::string& path() const { return path_; }
  /// Refused messages in the log (the rest were only counted).
  int64_t events_kept() const { return events_kept_; }
  /// Why the log stopped early (cannot be created or written); empty otherwise.
  const std::string& failure() const { return failure_; }

 private:
  std::string path_;
  std::unique_ptr<RunRecorder> log_;
  std::map<std::string, Channel> per_channel_;
  long total_ = 0;
  int64_t events_kept_ = 0;
  int64_t bytes_kept_ = 0;
  std::string failure_;
};

}  // namespace dream::node
