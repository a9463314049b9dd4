#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>

#include "command_line.h"
#include "commands.h"
#include "dream/workflows/lcm_tool_commands.h"
#include "lcm_java_tools.h"
#include "shared_options.h"
#include "window_display.h"

namespace dream::cli {
namespace {

struct SpyArgs {
  std::string log_path;  ///< empty: live traffic
  std::string lcm_url;   ///< empty: $LCM_DEFAULT_URL, or a private port for a log
  bool print_command_only = false;
};

}  // namespace

int RunSpy(const std::string& log_path, const std::string& lcm_url, bool print_command_only) {
  const std::string classpath = SpyClasspath();  // a missing jar is named before anything else
  const std::vector<std::vector<std::string>> commands =
      workflows::LcmToolCommands::Spy(classpath, log_path.empty() ? "" : RunLogPath(log_path), lcm_url);
  if (print_command_only) {
    PrintToolCommands(commands);
    return kExitOk;
  }
  RequireWindowDisplay("lcm-spy",
                       "without one, `dream spy --print` prints the command to run elsewhere, and "
                       "`dream log echo RUN CHANNEL` prints a log's messages as text");
  // lcm-spy gets 2 s to subscribe before the first message is played; closing it ends the session.
  return RunToolsUntilClosed(commands, 0, 2);
}

void DeclareSpyCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<SpyArgs>(
      "spy",
      "Open lcm-spy with the dream types, on live traffic or on a recorded log.\n"
      "Example: dream spy --log runs/go_to_goal/run.lcmlog",
      [](const SpyArgs& spy) { return RunSpy(spy.log_path, spy.lcm_url, spy.print_command_only); });
  command->add_option("--log", args->log_path,
                      "Replay this log (or a run folder's) into lcm-spy (on a private loopback port)");
  command->add_option("--lcm-url", args->lcm_url, "LCM URL to inspect (default $LCM_DEFAULT_URL)");
  command->add_flag("--print", args->print_command_only, "Print the commands instead of starting them");
}

}  // namespace dream::cli
