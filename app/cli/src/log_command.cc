#include <filesystem>
#include <nlohmann/json.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "command_line.h"
#include "commands.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/files/json_text.h"
#include "message_difference.h"
#include "message_json.h"
#include "shared_options.h"

namespace dream::cli {
namespace {

using Payloads = std::map<std::string, std::vector<std::vector<uint8_t>>>;

/// Each channel's messages in log order. Unless `raw`, a message equal to the
/// one before it on its channel is a resend and left out: a recording of the
/// bus (lcm-logger) holds the world's resends of a step and the agents'
/// answers to them, a run's own log holds each message once, and both hold
/// the same steps (no two different messages of a run are byte for byte the same).
Payloads PayloadsByChannel(const std::string& path, const std::regex& channels, bool raw) {
  Payloads payloads;
  for (lcm::LogRecord& record : lcm::LogReader::ReadAll(RunLogPath(path))) {
    if (!std::regex_match(record.channel, channels)) continue;
    lcm::ClearRandomIds(&record.data);  // every run and agent has its own id; the rest must match
    std::vector<std::vector<uint8_t>>& messages = payloads[record.channel];
    if (!raw && !messages.empty() && messages.back() == record.data) continue;
    messages.push_back(std::move(record.data));
  }
  return payloads;
}

/// Bytes of an LCM log event before its channel name: sync word, event
/// number, utime, channel length, data length.
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;

/// True for the channels DREAM publishes its own types on: a message there
/// that is not a DREAM type is damaged, not another program's.
bool IsDreamDataChannel(const std::string& channel) {
  for (const char* name : {lcm::kPosesChannel, lcm::kObstaclesChannel, lcm::kStatusChannel, lcm::kAppliedChannel}) {
    if (channel == name) return true;
  }
  for (const char* prefix : {lcm::kCommandChannelPrefix, lcm::kRadioChannelPrefix, lcm::kFaultChannelPrefix,
                             lcm::kLabCommandChannelPrefix}) {
    if (channel.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

struct LogEchoArgs {
  std::string log;
  std::string channel_regex;
  long long limit = 0;
};

struct LogDiffArgs {
  std::string first_log;
  std::string second_log;
  std::string channel_regex = ".*";
  bool raw = false;
};

}  // namespace

int RunLogInfo(const std::string& path_given) {
  const std::string path = RunLogPath(path_given);
  struct ChannelStats {
    long events = 0;
    long bytes = 0;
  };
  std::map<std::string, ChannelStats> stats;
  int64_t first = 0;
  int64_t last = 0;
  long total = 0;
  lcm::LogReader reader(path);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    if (total == 0) first = record.utime;
    last = record.utime;
    ++total;
    ChannelStats& s = stats[record.channel];
    ++s.events;
    s.bytes += static_cast<long>(record.data.size());
  }
  if (total == 0) throw std::runtime_error(path + ": an empty log (no events): nothing was recorded");
  std::cout << path << ": " << total << " events, " << fmt::format("{:.2f}", static_cast<double>(last - first) / 1e6)
            << " s of log time\n";  // to 0.01 s, not "6.66667 s"
  for (const auto& [channel, s] : stats) {
    std::cout << "  " << channel << ": " << s.events << " events, " << s.bytes << " bytes\n";
  }
  return kExitOk;
}

namespace {

/// `text` as the regular expression an option names; a bad one is an input
/// error naming the option.
std::regex ChannelRegex(const std::string& text, const std::string& option) {
  try {
    return std::regex(text);
  } catch (const std::regex_error& e) {
    throw std::invalid_argument(option + " '" + text + "' is not a regular expression: " + e.what());
  }
}

}  // namespace

namespace {

/// `dream log diff` exits as diff(1) and cmp(1) do, so a script can tell
/// "different" from "could not compare".
constexpr int kLogsDiffer = 1;
constexpr int kLogsNotCompared = 2;

}  // namespace

int RunLogDiff(const std::string& a, const std::string& b, const std::string& channel_regex, bool raw) {
  Payloads left;
  Payloads right;
  try {
    const std::regex channels = ChannelRegex(channel_regex, "--channels");
    left = PayloadsByChannel(a, channels, raw);
    right = PayloadsByChannel(b, channels, raw);
  } catch (const std::exception& e) {  // a missing or damaged log, a bad regex
    std::cerr << "dream: " << e.what() << '\n';
    return kLogsNotCompared;
  }
  bool same = true;
  for (const Payloads* side : {&left, &right}) {
    for (const auto& [channel, unused] : *side) {
      (void)unused;
      const auto l = left.find(channel);
      const auto r = right.find(channel);
      if (l == left.end() || r == right.end()) {
        std::cout << channel << ": only in " << (l == left.end() ? b : a) << '\n';
        same = false;
        continue;
      }
      if (side == &right) continue;  // compared once, from the left
      const size_t n = std::min(l->second.size(), r->second.size());
      for (size_t i = 0; i < n; ++i) {
        if (l->second[i] != r->second[i]) {
          std::cout << channel << ": message " << i << " differs first at "
                    << FirstDifference(l->second[i], r->second[i]) << '\n';
          same = false;
          break;
        }
      }
      if (l->second.size() != r->second.size()) {
        std::cout << channel << ": " << l->second.size() << " messages in " << a << ", " << r->second.size() << " in "
                  << b << '\n';
        same = false;
      }
    }
  }
  std::cout << (same ? "same" : "different") << " (channels matching '" << channel_regex << "')\n";
  return same ? kExitOk : kLogsDiffer;
}

int RunLogEcho(const std::string& path_given, const std::string& channel_regex, long long limit) {
  const std::string path = RunLogPath(path_given);
  const std::regex channels = ChannelRegex(channel_regex, "CHANNEL_REGEX");
  lcm::LogReader reader(path);
  lcm::LogRecord record;
  int64_t offset = 0;  // of the current event, for reports: LogReader does not tell
  int64_t event = 0;
  long long printed = 0;
  long long undecodable = 0;
  std::map<std::string, long long> skipped;  // channel -> events of no DREAM type
  std::map<std::string, long long> seen;     // every channel, for a regex that matches none
  while ((limit <= 0 || printed < limit) && reader.Next(&record)) {
    const int64_t event_offset = offset;
    offset += kEventHeaderBytes + static_cast<int64_t>(record.channel.size() + record.data.size());
    ++event;
    ++seen[record.channel];
    if (!std::regex_match(record.channel, channels)) continue;
    const MessageJson message(record.data);
    if (message.outcome() == MessageJson::Outcome::kDecoded) {
      nlohmann::ordered_json line = {{"channel", record.channel},
                                     {"utime", record.utime},
                                     {"type", message.type()},
                                     {"message", message.fields()}};
      std::cout << files::JsonText(line, -1) << '\n';
      ++printed;
    } else if (message.outcome() == MessageJson::Outcome::kUndecodable || IsDreamDataChannel(record.channel)) {
      // Reported and passed over: one damaged message must not hide the rest.
      std::cerr << path << ": byte " << event_offset << " (event " << event << ", " << record.channel
                << "): cannot decode " << record.data.size() << " bytes"
                << (message.type().empty() ? "" : " as " + message.type()) << ": " << message.problem() << '\n';
      ++undecodable;
    } else {
      ++skipped[record.channel];
    }
  }
  std::cout.flush();
  if (!skipped.empty()) {
    long long total = 0;
    std::string names;
    for (const auto& [channel, count] : skipped) {
      total += count;
      names += (names.empty() ? "" : ", ") + channel + " (" + std::to_string(count) + ")";
    }
    std::cerr << "skipped " << total << " events on channels of no DREAM type: " << names << '\n';
  }
  if (undecodable > 0) std::cerr << undecodable << " events could not be decoded (above)\n";
  if (printed == 0 && undecodable == 0 && skipped.empty()) {
    std::string names;
    for (const auto& [channel, count] : seen) names += (names.empty() ? "" : ", ") + channel;
    std::cerr << path << ": no event on a channel matching '" << channel_regex
              << "' (channels: " << (names.empty() ? "none" : names) << ")\n";
  }
  return kExitOk;
}

void DeclareLogCommand(CommandLine& line) {
  CLI::App* log = line.AddGroup("log",
                                "Look into recorded runs: info, diff, echo.\n"
                                "Example: dream log info runs/go_to_goal");

  const auto [info, info_path] = line.AddCommand<std::string>("info",
                                                              "Channels and event counts of a log.\n"
                                                              "Example: dream log info runs/go_to_goal/run.lcmlog",
                                                              RunLogInfo, log);
  AddRunLogArgument(info, "log", info_path);

  const auto [echo, echo_args] = line.AddCommand<LogEchoArgs>(
      "echo",
      "Print the decoded messages on channels matching CHANNEL_REGEX (whole name), one JSON object\n"
      "per line: {\"channel\", \"utime\" (the log's), \"type\", \"message\": the message's fields}; radio\n"
      "payloads as hex. Channels of no DREAM type are skipped and counted on stderr; an undecodable\n"
      "event is reported there with its byte offset.\n"
      "Example: dream log echo runs/go_to_goal 'DREAM_CMD_.*' --limit 5",
      [](const LogEchoArgs& args) { return RunLogEcho(args.log, args.channel_regex, args.limit); }, log);
  AddRunLogArgument(echo, "log", &echo_args->log);
  echo->add_option("channels", echo_args->channel_regex,
                   "Regex of channels to print, e.g. DREAM_POSES or 'DREAM_CMD_.*'")
      ->required();
  echo->add_option("--limit", echo_args->limit, "Stop after this many messages (default: all)")->check(StepCount());

  const auto [diff, diff_args] = line.AddCommand<LogDiffArgs>(
      "diff",
      "Compare two logs message by message, per channel, ignoring timestamps, run ids and agent ids\n"
      "(every run and agent process draws its own). Says where each channel first differs (step, robot, field).\n"
      "A message equal to the one before it on its channel is a resend and counted once, so an lcm-logger\n"
      "recording of a live run compares equal to the run's own log (--raw: every datagram as it is).\n"
      "Exit codes as diff(1): 0 equal, 1 different, 2 not compared (a missing or damaged log, a bad --channels).\n"
      "Example: dream log diff a/run.lcmlog b/run.lcmlog --channels DREAM_POSES",
      [](const LogDiffArgs& args) { return RunLogDiff(args.first_log, args.second_log, args.channel_regex, args.raw); },
      log);
  diff->add_option("a", diff_args->first_log, "First log (or run folder)")->required();
  diff->add_option("b", diff_args->second_log, "Second log (or run folder)")->required();
  diff->add_option("--channels", diff_args->channel_regex, "Regex of channels to compare")->capture_default_str();
  diff->add_flag("--raw", diff_args->raw, "Compare every datagram, resends included");
}

}  // namespace dream::cli
