#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <stdexcept>

#include "command_line.h"
#include "commands.h"
#include "dream/lcm/log_reader.h"

namespace dream::cli {
namespace {

using Payloads = std::map<std::string, std::vector<std::vector<uint8_t>>>;

/// The log of `path`: the file itself, or run.lcmlog in a run folder.
std::string LogFileOf(const std::string& path) {
  return std::filesystem::is_directory(path) ? (std::filesystem::path(path) / "run.lcmlog").string() : path;
}

Payloads PayloadsByChannel(const std::string& path, const std::regex& channels) {
  Payloads payloads;
  for (lcm::LogRecord& record : lcm::LogReader::ReadAll(LogFileOf(path))) {
    if (std::regex_match(record.channel, channels)) payloads[record.channel].push_back(std::move(record.data));
  }
  return payloads;
}

struct LogDiffArgs {
  std::string first_log;
  std::string second_log;
  std::string channel_regex = ".*";
};

}  // namespace

int RunLogInfo(const std::string& path_given) {
  const std::string path = LogFileOf(path_given);
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
  std::cout << path << ": " << total << " events, " << static_cast<double>(last - first) / 1e6
            << " s of log time\n";
  for (const auto& [channel, s] : stats) {
    std::cout << "  " << channel << ": " << s.events << " events, " << s.bytes << " bytes\n";
  }
  return kExitOk;
}

int RunLogDiff(const std::string& a, const std::string& b, const std::string& channel_regex) {
  const std::regex channels(channel_regex);
  const Payloads left = PayloadsByChannel(a, channels);
  const Payloads right = PayloadsByChannel(b, channels);
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
          std::cout << channel << ": message " << i << " differs\n";
          same = false;
          break;
        }
      }
      if (l->second.size() != r->second.size()) {
        std::cout << channel << ": " << l->second.size() << " messages in " << a << ", " << r->second.size()
                  << " in " << b << '\n';
        same = false;
      }
    }
  }
  std::cout << (same ? "same" : "different") << " (channels matching '" << channel_regex << "')\n";
  return same ? kExitOk : kExitInputError;
}

void DeclareLogCommand(CommandLine& line) {
  CLI::App* log = line.AddGroup("log", "Look into recorded runs: info, diff.\n"
                                       "Example: dream log info runs/go_to_goal");

  auto info_path = std::make_shared<std::string>();
  CLI::App* info = line.AddCommand(
      "info",
      "Channels and event counts of a log.\n"
      "Example: dream log info runs/go_to_goal/run.lcmlog",
      [info_path] { return RunLogInfo(*info_path); }, log);
  info->add_option("log", *info_path, "LCM log file, or a run folder (its run.lcmlog)")->required();

  auto diff_args = std::make_shared<LogDiffArgs>();
  CLI::App* diff = line.AddCommand(
      "diff",
      "Compare two logs message by message, per channel, ignoring timestamps. Exit 0 when equal.\n"
      "Example: dream log diff a/run.lcmlog b/run.lcmlog --channels DREAM_POSES",
      [diff_args] { return RunLogDiff(diff_args->first_log, diff_args->second_log, diff_args->channel_regex); }, log);
  diff->add_option("a", diff_args->first_log, "First log (or run folder)")->required();
  diff->add_option("b", diff_args->second_log, "Second log (or run folder)")->required();
  diff->add_option("--channels", diff_args->channel_regex, "Regex of channels to compare")->capture_default_str();
}

}  // namespace dream::cli
