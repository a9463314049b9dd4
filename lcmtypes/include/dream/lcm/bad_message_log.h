#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace dream::lcm {

/// Counts messages that could not be used (undecodable, foreign type,
/// invalid content) per channel and, where the message names one, per
/// sending agent, and logs them without flooding the terminal: the first
/// occurrence on a channel, then every 100th.
///
/// Memory stays bounded whatever arrives: at most kMaxChannels channels are
/// named, the rest are counted together under kOtherChannels; at most
/// kMaxSendersPerChannel agent ids are kept per channel.
class BadMessageLog {
 public:
  static constexpr size_t kMaxChannels = 256;
  static constexpr const char* kOtherChannels = "(other channels)";
  static constexpr size_t kMaxSendersPerChannel = 8;

  /// Records one bad message on `channel`; `reason` says what was wrong;
  /// `sender_agent_id` is the agent_id the message carried, if known.
  void Report(const std::string& channel, const std::string& reason,
              std::optional<int64_t> sender_agent_id = std::nullopt);

  /// Bad messages seen on `channel` so far (0 for a channel counted under kOtherChannels).
  long count(const std::string& channel) const;

  /// Bad messages over all channels.
  long total() const { return total_; }

  /// Per channel name (and kOtherChannels once the table is full).
  const std::map<std::string, long>& per_channel() const { return per_channel_; }

  /// The first agent ids seen sending bad messages, per channel.
  const std::map<std::string, std::set<int64_t>>& senders() const { return senders_; }

 private:
  std::map<std::string, long> per_channel_;
  std::map<std::string, std::set<int64_t>> senders_;
  long total_ = 0;
};

}  // namespace dream::lcm
