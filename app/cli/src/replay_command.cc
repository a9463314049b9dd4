#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "command_line.h"
#include "commands.h"
#include "dream/files/regular_file.h"
#include "lcm_java_tools.h"
#include "dream/process/process_group.h"
#include "shared_options.h"
#include "dream/workflows/lcm_tool_commands.h"
#include "window_display.h"

namespace dream::cli {
namespace {

// Every event of an LCM log starts with this sync word (big-endian).
constexpr unsigned char kLcmLogSyncWord[4] = {0xED, 0xA1, 0xDA, 0x01};

/// The log to play: `run` itself, or run.lcmlog inside a run folder.
/// @throws std::runtime_error naming the path when it is missing, empty or not an LCM log.
std::string LogToReplay(const std::string& run) {
  const std::string log = RunLogPath(run);
  const files::RegularFile file(log);  // a FIFO or device is refused, not waited on
  unsigned char head[4] = {0, 0, 0, 0};
  const ssize_t got = ::pread(file.descriptor(), head, sizeof(head), 0);
  if (got != static_cast<ssize_t>(sizeof(head))) {
    throw std::runtime_error(log + ": " + (got >= 0 ? "empty or shorter than one event" : "cannot be read") +
                             "; not an LCM log");
  }
  if (!std::equal(head, head + 4, kLcmLogSyncWord)) {
    throw std::runtime_error(log + ": not an LCM log (it does not start with an event's sync word 0xEDA1DA01)");
  }
  return log;
}

}  // namespace

int RunReplay(const ReplayArgs& args) {
  const std::string log = LogToReplay(args.run);
  const std::string lcm_jar = RequireLcmJar();
  const std::string url = workflows::LcmToolCommands::Url(args.lcm_url);
  const std::vector<std::string> player = workflows::LcmToolCommands::Player(lcm_jar, log, url, args.paused);
  std::vector<std::string> spy;
  if (args.with_spy) {
    SpyClasspath();  // what the spy needs, named now: a spy that cannot start would leave the replay unwatched
    spy = {process::SelfExecutable(), "spy", "--lcm-url=" + url};
  }
  if (args.print_command_only) {
    PrintToolCommands({spy, player});  // in the order to start them
    return kExitOk;
  }
  RequireWindowDisplay("LCM's log player",
                       "without one, `dream replay RUN --print` prints the command to run elsewhere, and "
                       "lcm-logplayer RUN/run.lcmlog plays the log with no window");
  spdlog::info("replaying {} on {}{}", log, url, args.with_spy ? " into lcm-spy" : "");
  // The spy gets 2 s to start and subscribe before the player plays the log's
  // first message (it missed the start when both started at once); the
  // player's window ends the replay.
  return RunToolsUntilClosed({spy, player}, 1, 2);
}

void DeclareReplayCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<ReplayArgs>(
      "replay",
      "Play a recorded run on LCM through LCM's log player window: seek with the slider, pause, step,\n"
      "change the speed, mute channels. Watch it with dream spy, or any LCM tool, on the same URL.\n"
      "Example: dream replay runs/go_to_goal --spy",
      RunReplay);
  AddRunLogArgument(command, "run", &args->run);
  command->add_option("--lcm-url", args->lcm_url,
                      "LCM URL to play on (default $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");
  command->add_flag("--paused", args->paused, "Open the log paused at its start");
  command->add_flag("--spy", args->with_spy, "Also open lcm-spy (dream spy) on the same URL");
  command->add_flag("--print,--print-command", args->print_command_only, "Print the commands instead of starting them");
}

}  // namespace dream::cli
