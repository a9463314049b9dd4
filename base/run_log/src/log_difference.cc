#include "dream/run_log/log_difference.h"

#include <algorithm>
#include <cstdint>
#include <map>

#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/run_log/message_difference.h"

namespace dream::run_log {
namespace {

using Payloads = std::map<std::string, std::vector<std::vector<uint8_t>>>;

/// Each channel's messages in log order. Unless `raw`, a message equal to the
/// one before it on its channel is a resend and left out: a recording of the
/// bus (lcm-logger) holds the world's resends of a step and the agents'
/// answers to them, a run's own log holds each message once, and both hold
/// the same steps (no two different messages of a run are byte for byte the same).
Payloads PayloadsByChannel(const std::string& path, const std::regex& channels, bool raw) {
  Payloads payloads;
  for (lcm::LogRecord& record : lcm::LogReader::ReadAll(path)) {
    if (!std::regex_match(record.channel, channels)) continue;
    lcm::ClearRandomIds(&record.data);  // every run and agent has its own id; the rest must match
    std::vector<std::vector<uint8_t>>& messages = payloads[record.channel];
    if (!raw && !messages.empty() && messages.back() == record.data) continue;
    messages.push_back(std::move(record.data));
  }
  return payloads;
}

}  // namespace

LogDifference LogDifference::Compare(const Log& first, const Log& second, const std::regex& channels, bool raw) {
  const Payloads left = PayloadsByChannel(first.path, channels, raw);
  const Payloads right = PayloadsByChannel(second.path, channels, raw);
  const std::string& first_log = first.name;
  const std::string& second_log = second.name;
  LogDifference difference;
  std::vector<std::string>& lines = difference.differences_;
  for (const Payloads* side : {&left, &right}) {
    for (const auto& [channel, unused] : *side) {
      (void)unused;
      const auto l = left.find(channel);
      const auto r = right.find(channel);
      if (l == left.end() || r == right.end()) {
        lines.push_back(channel + ": only in " + (l == left.end() ? second_log : first_log));
        continue;
      }
      if (side == &right) continue;  // compared once, from the left
      const size_t n = std::min(l->second.size(), r->second.size());
      for (size_t i = 0; i < n; ++i) {
        if (l->second[i] != r->second[i]) {
          lines.push_back(channel + ": message " + std::to_string(i) + " differs first at " +
                          FirstDifference(l->second[i], r->second[i]));
          break;
        }
      }
      if (l->second.size() != r->second.size()) {
        lines.push_back(channel + ": " + std::to_string(l->second.size()) + " messages in " + first_log + ", " +
                        std::to_string(r->second.size()) + " in " + second_log);
      }
    }
  }
  return difference;
}

}  // namespace dream::run_log
