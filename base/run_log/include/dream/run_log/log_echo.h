#pragma once

#include <ostream>
#include <regex>
#include <string>

namespace dream::run_log {

/// The messages of an LCM log decoded as JSON, one object per line:
/// {"channel", "utime" (the log's), "type", "message": its fields}, as
/// `dream log echo` prints them. An event that does not decode is reported
/// with its byte offset and passed over (one damaged message must not hide
/// the rest); channels of no DREAM type are skipped and counted.
class LogEcho {
 public:
  struct Options {
    std::string path;           ///< the log file
    std::regex channels;        ///< whole channel names to print
    std::string channels_text;  ///< `channels` as the user wrote it, for messages
    long long limit = 0;        ///< stop after this many messages; <= 0: all
  };

  /// Writes the JSON lines to `out`, and what was skipped or could not be
  /// decoded (or that no channel matched) to `problems`.
  /// @throws std::runtime_error for a missing log or one cut mid-event.
  static void Print(const Options& options, std::ostream& out, std::ostream& problems);
};

}  // namespace dream::run_log
