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
  /// The first reason kept per channel is cut to this many bytes (it may quote the message).
  static constexpr size_t kMaxReasonBytes = 300;

  /// The first bad message of a channel: what was wrong, and when.
  struct First {
    std::string reason;
    int64_t step = -1;  ///< the owner's step then (set_step), -1 when it keeps none
  };

  /// Records one bad message on `channel`; `reason` says what was wrong;
  /// `sender_agent_id` is the agent_id the message carried, if known.
  void Report(const std::string& channel, const std::string& reason,
              std::optional<int64_t> sender_agent_id = std::nullopt);

  /// The step the owner is at, kept with each channel's first bad message
  /// (the world sets it as it steps).
  void set_step(int64_t step) { step_ = step; }

  /// Per channel of per_channel(), its first bad message.
  const std::map<std::string, First>& first() const { return first_; }

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
  std::map<std::string, First> first_;
  long total_ = 0;
  int64_t step_ = -1;
};

}  // namespace dream::lcm
