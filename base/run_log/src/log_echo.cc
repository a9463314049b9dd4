#include "dream/run_log/log_echo.h"

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>

#include "dream/files/json_text.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/log_reader.h"
#include "dream/run_log/message_json.h"

namespace dream::run_log {
namespace {

/// Bytes of an LCM log event before its channel name: sync word, event
/// number, utime, channel length, data length.
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;

/// True for the channels DREAM publishes its own types on: a message there
/// that is not a DREAM type is damaged, not another program's.
bool IsDreamDataChannel(const std::string& channel) {
  for (const char* name :
       {lcm::kPosesChannel, lcm::kObstaclesChannel, lcm::kStatusChannel, lcm::kAppliedChannel, lcm::kCommandsChannel}) {
    if (channel == name) return true;
  }
  for (const char* prefix : {lcm::kCommandChannelPrefix, lcm::kRadioChannelPrefix, lcm::kFaultChannelPrefix,
                             lcm::kBusyChannelPrefix, lcm::kLabCommandChannelPrefix}) {
    if (channel.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

/// "A (3), B (1)": channels with their counts.
std::string CountedNames(const std::map<std::string, long long>& counts, long long* total) {
  std::string names;
  for (const auto& [channel, count] : counts) {
    *total += count;
    names += (names.empty() ? "" : ", ") + channel + " (" + std::to_string(count) + ")";
  }
  return names;
}

}  // namespace

void LogEcho::Print(const Options& options, std::ostream& out, std::ostream& problems) {
  const std::string& path = options.path;
  lcm::LogReader reader(path);
  lcm::LogRecord record;
  int64_t offset = 0;  // of the current event, for reports: LogReader does not tell
  int64_t event = 0;
  long long printed = 0;
  long long undecodable = 0;
  std::map<std::string, long long> skipped;  // channel -> events of no DREAM type
  std::map<std::string, long long> seen;     // every channel, for a regex that matches none
  while ((options.limit <= 0 || printed < options.limit) && reader.Next(&record)) {
    const int64_t event_offset = offset;
    offset += kEventHeaderBytes + static_cast<int64_t>(record.channel.size() + record.data.size());
    ++event;
    ++seen[record.channel];
    if (!std::regex_match(record.channel, options.channels)) continue;
    const MessageJson message(record.data);
    if (message.outcome() == MessageJson::Outcome::kDecoded) {
      nlohmann::ordered_json line = {{"channel", record.channel},
                                     {"utime", record.utime},
                                     {"type", message.type()},
                                     {"message", message.fields()}};
      out << files::JsonText(line, -1) << '\n';
      ++printed;
    } else if (message.outcome() == MessageJson::Outcome::kUndecodable || IsDreamDataChannel(record.channel)) {
      problems << path << ": byte " << event_offset << " (event " << event << ", " << record.channel
               << "): cannot decode " << record.data.size() << " bytes"
               << (message.type().empty() ? "" : " as " + message.type()) << ": " << message.problem() << '\n';
      ++undecodable;
    } else {
      ++skipped[record.channel];
    }
  }
  out.flush();
  if (!skipped.empty()) {
    long long total = 0;
    const std::string names = CountedNames(skipped, &total);
    problems << "skipped " << total << " events on channels of no DREAM type: " << names << '\n';
  }
  if (undecodable > 0) problems << undecodable << " events could not be decoded (above)\n";
  if (printed == 0 && undecodable == 0 && skipped.empty()) {
    std::string names;
    for (const auto& [channel, count] : seen) names += (names.empty() ? "" : ", ") + channel;
    problems << path << ": no event on a channel matching '" << options.channels_text
             << "' (channels: " << (names.empty() ? "none" : names) << ")\n";
  }
}

}  // namespace dream::run_log
