#pragma once

#include <map>
#include <string>

namespace dream::lcm {

/// Counts messages that could not be used (undecodable, foreign type,
/// invalid content) per channel and logs them without flooding the terminal:
/// the first occurrence on a channel, then every 100th.
class BadMessageLog {
 public:
  /// Records one bad message on `channel`; `reason` says what was wrong.
  void Report(const std::string& channel, const std::string& reason);

  /// Bad messages seen on `channel` so far.
  long count(const std::string& channel) const;

  /// Bad messages over all channels.
  long total() const { return total_; }

  const std::map<std::string, long>& per_channel() const { return per_channel_; }

 private:
  std::map<std::string, long> per_channel_;
  long total_ = 0;
};

}  // namespace dream::lcm
