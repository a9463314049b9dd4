#include "dream/lcm/bad_message_log.h"

#include <spdlog/spdlog.h>

namespace dream::lcm {

void BadMessageLog::Report(const std::string& channel, const std::string& reason,
                           std::optional<int64_t> sender_agent_id) {
  // Channel names come from the network: past the cap they share one entry,
  // so a flood of made-up names costs a counter, not a map node each.
  auto entry = per_channel_.find(channel);
  if (entry == per_channel_.end()) {
    const size_t named = per_channel_.size() - per_channel_.count(kOtherChannels);
    entry = per_channel_.emplace(named < kMaxChannels ? channel : kOtherChannels, 0).first;
  }
  const long seen = ++entry->second;
  ++total_;
  if (seen == 1) first_[entry->first] = First{reason.substr(0, kMaxReasonBytes), step_};
  if (sender_agent_id) {
    std::set<int64_t>& senders = senders_[entry->first];
    if (senders.size() < kMaxSendersPerChannel) senders.insert(*sender_agent_id);
  }
  if (seen == 1 || seen % 100 == 0) {
    spdlog::warn("{}: dropped bad message #{}: {}{}", channel, seen, reason,
                 sender_agent_id ? fmt::format(" (from agent {})", *sender_agent_id) : "");
  }
}

long BadMessageLog::count(const std::string& channel) const {
  const auto it = per_channel_.find(channel);
  return it == per_channel_.end() ? 0 : it->second;
}

}  // namespace dream::lcm
