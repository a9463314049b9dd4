// dream: run distributed multi-robot controllers against the Robotarium-
// faithful simulator, one process or many, inspect the runs, and carry them
// to the real Robotarium and back.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "dream/config/config_error.h"
#include "dream/config/name_suggestion.h"
#include "dream/files/stopped.h"

namespace {

/// CLI11 would only say "A subcommand is required"; this names the unknown
/// word. Options before the subcommand are the global ones only; the first
/// other word must be a subcommand. 0 when the words are known, else the
/// exit code (the message is printed).
int RefuseUnknownWordsBeforeParsing(CLI::App& app, int argc, char** argv) {
  using dream::cli::kExitUsage;
  int first_word = 1;
  for (; first_word < argc && argv[first_word][0] == '-'; ++first_word) {
    const std::string option = argv[first_word];
    if (option != "-q" && option != "--quiet" && option != "-v" && option != "--verbose" && option != "-h" &&
        option != "--help" && option != "--version") {
      std::cerr << "dream: unknown option '" << option
                << "' before the subcommand; global options are -q, -v, -h, --version"
                << " (dream --help)\n";
      return kExitUsage;
    }
  }
  if (first_word >= argc) return 0;
  std::string names;
  std::vector<std::string> name_list;
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->get_name() == argv[first_word]) return 0;
    names += (names.empty() ? "" : ", ") + command->get_name();
    name_list.push_back(command->get_name());
  }
  std::cerr << "dream: unknown subcommand '" << argv[first_word] << "'"
            << dream::config::DidYouMean(argv[first_word], name_list) << "; known: " << names << " (dream --help)\n";
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace dream::cli;
  CommandLine line{
      "dream: distributed multi-robot controllers on a Robotarium-faithful simulator, over LCM.\n"
      "Exit codes: 0 ok, 1 bad input, 2 usage, 3 run has hard errors (the Robotarium would reject it),\n"
      "4 run did not finish (or a controller failed), 5 run not ready (robots lost, command conflicts,\n"
      "bad messages, goal missed: summary.json verdict_reasons), 130 interrupted.\n"
      "dream log diff exits as diff(1): 0 equal, 1 different, 2 not compared.",
      "dream"};
  CLI::App& app = line.app();
  app.require_subcommand(1);
  app.fallthrough();  // --quiet/--verbose work after the subcommand too
  bool quiet = false;
  bool verbose = false;
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors (no progress either)");
  app.add_flag("-v,--verbose", verbose, "Debug output");
  app.set_version_flag("--version", VersionLine(), "Print the version (PROJECT_VERSION and git commit) and exit");

  // Each command declares its options and action in its own file; this
  // order is the order of `dream --help`.
  DeclareRunCommand(line);
  DeclareSimCommand(line);
  DeclareAgentCommand(line);
  DeclareLaunchCommand(line);
  DeclareSpyCommand(line);
  DeclareReplayCommand(line);
  DeclareLogCommand(line);
  DeclareBridgeCommands(line);    // export, import, lab-replay, compare, check-submission (docs/robotarium.md)
  DeclareCalibrateCommand(line);  // fit the lab model to real runs (docs/experiments.md)
  DeclareSweepCommand(line);
  DeclareRenderCommand(line);  // pictures and videos (docs/rendering.md)
  DeclareViewCommand(line);    // the live arena in a browser (docs/view.md)
  DeclareVersionCommand(line);

  if (const int refused = RefuseUnknownWordsBeforeParsing(app, argc, argv)) return refused;

  try {
    line.Parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    // One line, like every other failure, and where to read more.
    const bool extra_words = dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr;
    std::cerr << "dream: " << e.what() << line.SuggestionAfterFailedParse()
              << (extra_words ? line.ScriptArgumentsHint() : "") << " (" << line.ParsedCommandName() << " --help)\n";
    return kExitUsage;
  }

  spdlog::set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
  spdlog::set_level(quiet ? spdlog::level::warn : verbose ? spdlog::level::debug : spdlog::level::info);
  InstallStopSignals();

  try {
    if (const CommandLine::Action action = line.ChosenAction()) return action();
  } catch (const dream::files::Stopped& e) {  // a long computation saw Ctrl-C or SIGTERM
    std::cerr << "dream: " << e.what() << '\n';
    return kExitInterrupted;
  } catch (const std::exception& e) {  // config::ConfigError included
    std::cerr << "dream: " << e.what() << '\n';
    // Ctrl-C while a controller was being set up (a Python setup() that hangs) is an interruption.
    return StopFlag().load() ? kExitInterrupted : kExitInputError;
  }
  return kExitUsage;
}
