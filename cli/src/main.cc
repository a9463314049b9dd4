// dream: run distributed multi-robot controllers against the Robotarium-
// faithful simulator, one process or many, and inspect the runs.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <iostream>

#include "commands.h"
#include "dream/config/config_error.h"

namespace {

void AddRunOptions(CLI::App* command, dream::cli::RunArgs* args, const char* url_help) {
  command->add_option("config", args->config_path, "Run config (YAML), e.g. config/go_to_goal.yaml")->required();
  command->add_option("--out", args->out_dir, "Output folder for run.lcmlog and summary.json (default runs/<name>)");
  command->add_option("--lcm-url", args->lcm_url, url_help);
  command->add_option("--steps", args->steps, "Override the config's step limit")
      ->check(CLI::Validator(
          [](const std::string& text) {
            return text.find_first_not_of("0123456789") == std::string::npos && text.find_first_not_of('0') != std::string::npos
                       ? std::string()
                       : "must be a whole number >= 1, got " + text;
          },
          "INT>=1"));
  command->add_option("--mode", args->mode, "Override the world mode")->check(CLI::IsMember({"lockstep", "realtime"}));
  command->add_flag("--all-steps", args->all_steps, "Run every step even when all robots report done (benchmarks)");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace dream::cli;
  CLI::App app{
      "dream: distributed multi-robot controllers on a Robotarium-faithful simulator, over LCM.\n"
      "Exit codes: 0 ok, 1 bad input, 2 usage, 3 run has hard errors (the Robotarium would reject it),\n"
      "4 run did not finish, 130 interrupted.",
      "dream"};
  app.require_subcommand(1);
  app.fallthrough();  // --quiet/--verbose work after the subcommand too
  bool quiet = false;
  bool verbose = false;
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors");
  app.add_flag("-v,--verbose", verbose, "Debug output");

  RunArgs run_args;
  CLI::App* run = app.add_subcommand(
      "run", "Run an experiment in one process: the simulator and every robot's agent on one bus.\n"
             "Example: dream run config/go_to_goal.yaml --out runs/demo");
  AddRunOptions(run, &run_args, "LCM URL (default memq://, in-process)");

  RunArgs sim_args;
  CLI::App* sim = app.add_subcommand(
      "sim", "Run only the simulator; agents run elsewhere (dream agent) on the same LCM URL.\n"
             "Example: dream sim config/go_to_goal.yaml --lcm-url 'udpm://239.255.76.67:7667?ttl=0'");
  AddRunOptions(sim, &sim_args, "LCM URL (default $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");

  AgentArgs agent_args;
  CLI::App* agent = app.add_subcommand(
      "agent", "Run the agents of some robots against whichever world is on the bus.\n"
               "Example: dream agent config/go_to_goal.yaml --robots 0-2");
  agent->add_option("config", agent_args.config_path, "Run config (YAML)")->required();
  agent->add_option("--robots", agent_args.robots, "Robots to drive: all, 3, 0,2,5 or 0-4")->capture_default_str();
  agent->add_option("--lcm-url", agent_args.lcm_url, "LCM URL (default $LCM_DEFAULT_URL)");
  agent->add_option("--idle-timeout", agent_args.idle_timeout_s, "Give up after this many seconds without poses")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  RunArgs launch_args;
  CLI::App* launch = app.add_subcommand(
      "launch", "Run the simulator and one agent process per robot over udpm.\n"
                "Example: dream launch config/go_to_goal.yaml");
  AddRunOptions(launch, &launch_args, "LCM URL (default $LCM_DEFAULT_URL)");

  std::string spy_log;
  std::string spy_url;
  bool spy_print = false;
  CLI::App* spy = app.add_subcommand(
      "spy", "Open lcm-spy with the dream types, on live traffic or on a recorded log.\n"
             "Example: dream spy --log runs/go_to_goal/run.lcmlog");
  spy->add_option("--log", spy_log, "Replay this log into lcm-spy (on a private loopback port)");
  spy->add_option("--lcm-url", spy_url, "LCM URL to inspect (default $LCM_DEFAULT_URL)");
  spy->add_flag("--print", spy_print, "Print the commands instead of starting them");

  CLI::App* log = app.add_subcommand("log", "Look into recorded runs.");
  log->require_subcommand(1);
  std::string info_path;
  CLI::App* log_info = log->add_subcommand("info", "Channels and event counts of a log.\n"
                                                   "Example: dream log info runs/go_to_goal/run.lcmlog");
  log_info->add_option("log", info_path, "LCM log file")->required();
  std::string diff_a;
  std::string diff_b;
  std::string diff_channels = ".*";
  CLI::App* log_diff = log->add_subcommand(
      "diff", "Compare two logs message by message, per channel, ignoring timestamps. Exit 0 when equal.\n"
              "Example: dream log diff a/run.lcmlog b/run.lcmlog --channels DREAM_POSES");
  log_diff->add_option("a", diff_a, "First log")->required();
  log_diff->add_option("b", diff_b, "Second log")->required();
  log_diff->add_option("--channels", diff_channels, "Regex of channels to compare")->capture_default_str();

  // CLI11 would only say "A subcommand is required"; name the unknown word.
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const CLI::App* command : app.get_subcommands({})) {
      known = known || command->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + command->get_name();
    }
    if (!known) {
      std::cerr << "dream: unknown subcommand '" << argv[1] << "'; known: " << names << " (dream --help)\n";
      return kExitUsage;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }

  spdlog::set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
  spdlog::set_level(quiet ? spdlog::level::warn : verbose ? spdlog::level::debug : spdlog::level::info);
  InstallStopSignals();

  try {
    if (*run) return RunEmbedded(run_args);
    if (*sim) return RunSimOnly(sim_args);
    if (*agent) return ExecAgentBinary(argc, argv);
    if (*launch) return RunLaunch(launch_args);
    if (*log_info) return RunLogInfo(info_path);
    if (*log_diff) return RunLogDiff(diff_a, diff_b, diff_channels);
    if (*spy) return RunSpy(spy_log, spy_url, spy_print);
  } catch (const dream::config::ConfigError& e) {
    std::cerr << "dream: " << e.what() << '\n';
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "dream: " << e.what() << '\n';
    return kExitInputError;
  }
  return kExitUsage;
}
