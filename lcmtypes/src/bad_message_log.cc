#include "dream/lcm/bad_message_log.h"

#include <spdlog/spdlog.h>

namespace dream::lcm {

void BadMessageLog::Report(const std::string& channel, const std::string& reason) {
  const long seen = ++per_channel_[channel];
  ++total_;
  if (seen == 1 || seen % 100 == 0) {
    spdlog::warn("{}: dropped bad message #{}: {}", channel, seen, reason);
  }
}

long BadMessageLog::count(const std::string& channel) const {
  const auto it = per_channel_.find(channel);
  return it == per_channel_.end() ? 0 : it->second;
}

}  // namespace dream::lcm
