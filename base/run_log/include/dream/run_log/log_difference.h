#pragma once

#include <regex>
#include <string>
#include <vector>

namespace dream::run_log {

/// Two LCM logs compared message by message, per channel, ignoring
/// timestamps, run ids and agent ids (every run and agent process draws its
/// own): what `dream log diff` prints. Unless `raw`, a message equal to the one
/// before it on its channel is a resend and counted once, so an lcm-logger
/// recording of a live run compares equal to the run's own log.
class LogDifference {
 public:
  /// One of the logs compared: the file read, and the name the differences
  /// call it by (what the user gave: a run folder or the file).
  struct Log {
    std::string path;
    std::string name;
  };

  /// Compares the channels of `first` and `second` whose whole name matches
  /// `channels`; the first log is read whole before the second.
  /// @throws std::runtime_error for a missing or damaged log.
  static LogDifference Compare(const Log& first, const Log& second, const std::regex& channels, bool raw);

  bool same() const { return differences_.empty(); }
  /// One line per difference, in channel order: "DREAM_POSES: message 3
  /// differs first at step 3, robot 1: x 0.5 vs 0.51", "DREAM_CMD_2: only in
  /// b.lcmlog", "DREAM_STATUS: 10 messages in a.lcmlog, 9 in b.lcmlog".
  const std::vector<std::string>& differences() const { return differences_; }

 private:
  std::vector<std::string> differences_;
};

}  // namespace dream::run_log
