// dream log info / diff / echo: what a log holds, two logs compared, its
// messages as JSON. The work is dream::run_log's (through
// workflows::LogWorkflow); this file is options and exit codes.
#include <iostream>
#include <regex>
#include <stdexcept>

#include "command_line.h"
#include "commands.h"
#include "dream/workflows/log_workflow.h"
#include "shared_options.h"

namespace dream::cli {
namespace {

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

/// `text` as the regular expression an option names; a bad one is an input
/// error naming the option.
std::regex ChannelRegex(const std::string& text, const std::string& option) {
  try {
    return std::regex(text);
  } catch (const std::regex_error& e) {
    throw std::invalid_argument(option + " '" + text + "' is not a regular expression: " + e.what());
  }
}

/// `dream log diff` exits as diff(1) and cmp(1) do, so a script can tell
/// "different" from "could not compare".
constexpr int kLogsDiffer = 1;
constexpr int kLogsNotCompared = 2;

}  // namespace

int RunLogInfo(const std::string& path_given) {
  workflows::LogWorkflow().Info(RunLogPath(path_given));
  return kExitOk;
}

int RunLogDiff(const std::string& a, const std::string& b, const std::string& channel_regex, bool raw) {
  bool same = false;
  try {
    const std::regex channels = ChannelRegex(channel_regex, "--channels");
    const std::string a_path = RunLogPath(a);
    const std::string b_path = RunLogPath(b);
    same = workflows::LogWorkflow().Diff(a_path, a, b_path, b, channels, channel_regex, raw);
  } catch (const std::exception& e) {  // a missing or damaged log, a bad regex
    std::cerr << "dream: " << e.what() << '\n';
    return kLogsNotCompared;
  }
  return same ? kExitOk : kLogsDiffer;
}

int RunLogEcho(const std::string& path_given, const std::string& channel_regex, long long limit) {
  const std::string path = RunLogPath(path_given);  // a missing log named before a bad regex
  workflows::LogWorkflow().Echo(path, ChannelRegex(channel_regex, "CHANNEL_REGEX"), channel_regex, limit);
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
