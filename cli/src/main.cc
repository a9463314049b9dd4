// dream: run distributed multi-robot controllers against the Robotarium-
// faithful simulator, one process or many, inspect the runs, and carry them
// to the real Robotarium and back.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <iostream>

#include "commands.h"
#include "dream/config/config_error.h"

namespace {

/// --steps: a whole number >= 1, with a message that says so (CLI::PositiveNumber
/// would take 2.5 and quote a 300-digit range).
CLI::Validator StepCount() {
  return CLI::Validator(
      [](const std::string& text) {
        return text.find_first_not_of("0123456789") == std::string::npos && text.find_first_not_of('0') != std::string::npos
                   ? std::string()
                   : "must be a whole number >= 1, got " + text;
      },
      "INT>=1");
}

/// "dream log info": the (sub)command line a failed parse got to, for a pointer to its --help.
std::string ParsedCommand(const CLI::App& app) {
  std::string command = app.get_name();
  for (const CLI::App* at = &app; !at->get_subcommands().empty();) {
    at = at->get_subcommands().front();
    command += " " + at->get_name();
  }
  return command;
}

void AddRunOptions(CLI::App* command, dream::cli::RunArgs* args, const char* url_help) {
  command->add_option("config", args->config_path, "Run config (YAML), e.g. config/go_to_goal.yaml")->required();
  command->add_option("--out", args->out_dir, "Output folder for run.lcmlog and summary.json (default runs/<name>)");
  command->add_option("--lcm-url", args->lcm_url, url_help);
  command->add_option("--steps", args->steps, "Override the config's step limit")->check(StepCount());
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
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors (no progress either)");
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

  CLI::App* log = app.add_subcommand("log", "Look into recorded runs: info, diff.\n"
                                             "Example: dream log info runs/go_to_goal");
  log->require_subcommand(1);
  std::string info_path;
  CLI::App* log_info = log->add_subcommand("info", "Channels and event counts of a log.\n"
                                                   "Example: dream log info runs/go_to_goal/run.lcmlog");
  log_info->add_option("log", info_path, "LCM log file, or a run folder (its run.lcmlog)")->required();
  std::string diff_a;
  std::string diff_b;
  std::string diff_channels = ".*";
  CLI::App* log_diff = log->add_subcommand(
      "diff", "Compare two logs message by message, per channel, ignoring timestamps. Exit 0 when equal.\n"
              "Example: dream log diff a/run.lcmlog b/run.lcmlog --channels DREAM_POSES");
  log_diff->add_option("a", diff_a, "First log (or run folder)")->required();
  log_diff->add_option("b", diff_b, "Second log (or run folder)")->required();
  log_diff->add_option("--channels", diff_channels, "Regex of channels to compare")->capture_default_str();

  // The bridge to the Robotarium (docs/robotarium.md).
  ExportArgs export_args;
  CLI::App* export_command = app.add_subcommand(
      "export", "Turn a recorded run into a Robotarium submission (a main script plus .npy data), after\n"
                "checking it as the lab would: robots, duration, start poses, boundary and collision errors.\n"
                "Example: dream export runs/go_to_goal --out exports/go_to_goal");
  export_command->add_option("run", export_args.run_dir, "Run folder written by dream run (run.lcmlog, config.yaml)")
      ->required();
  export_command->add_option("--out", export_args.out_dir, "Output folder (default exports/<name>)");
  export_command->add_option("--config", export_args.config_path, "The run's config (default <run>/config.yaml)");
  export_command->add_option("--strategy", export_args.strategy,
                             "track: recorded commands plus feedback on the pose error; replay: open loop")
      ->check(CLI::IsMember({"track", "replay"}))
      ->capture_default_str();
  export_command->add_flag("--barriers", export_args.barriers,
                           "Pass commands through the Robotarium's barrier certificates (safety layer)");
  export_command->add_option("--settle-steps", export_args.settle_steps,
                             "At most this many steps to settle on the start poses before step 0")
      ->check(CLI::Range(0, 3000))
      ->capture_default_str();

  ImportArgs import_args;
  CLI::App* import_command = app.add_subcommand(
      "import", "Turn what the lab returned (dream_result.npy, or dream_result.mat from MATLAB) into a run\n"
                "folder like dream run writes: run.lcmlog, summary.json, trajectories.png.\n"
                "Example: dream import ~/Downloads/dream_result.npy --export exports/go_to_goal --out runs/lab1");
  import_command->add_option("result", import_args.result, "dream_result.npy / .mat, or a folder holding one")
      ->required();
  import_command->add_option("--export", import_args.export_dir, "The folder dream export wrote")->required();
  import_command->add_option("--out", import_args.out_dir, "Output folder (default runs/<name>_lab)");

  LabReplayArgs replay_args;
  CLI::App* replay_command = app.add_subcommand(
      "lab-replay", "Run a lab run (from dream import) as the world on the bus: the agents get the lab's poses\n"
                    "and their commands are recorded beside the lab's. Agents run in this process (memq://)\n"
                    "unless --world-only.\n"
                    "Example: dream lab-replay runs/lab1 --out runs/lab1_replay");
  replay_command->add_option("lab", replay_args.lab_dir, "Run folder written by dream import")->required();
  replay_command->add_option("--out", replay_args.out_dir, "Output folder (default runs/<name>_lab_replay)");
  replay_command->add_option("--lcm-url", replay_args.lcm_url,
                             "LCM URL (default memq://, or $LCM_DEFAULT_URL with --world-only)");
  replay_command->add_option("--steps", replay_args.steps, "Replay at most this many steps")->check(StepCount());
  replay_command->add_option("--mode", replay_args.mode, "Override the world mode")
      ->check(CLI::IsMember({"lockstep", "realtime"}));
  replay_command->add_flag("--world-only", replay_args.world_only,
                           "Only the world; start the agents elsewhere (dream agent CONFIG) on the same URL");

  CompareArgs compare_args;
  CLI::App* compare_command = app.add_subcommand(
      "compare", "Compare a simulated run with its lab run: tracking error per robot, closest approach,\n"
                 "violations and the experiment's metrics side by side; writes comparison.json and .png.\n"
                 "Example: dream compare runs/go_to_goal runs/lab1");
  compare_command->add_option("simulated", compare_args.first_dir, "The simulated run's folder")->required();
  compare_command->add_option("lab", compare_args.second_dir, "The lab run's folder (dream import)")->required();
  compare_command->add_option("--out", compare_args.out_dir, "Output folder (default: the lab run's folder)");

  CheckSubmissionArgs check_args;
  CLI::App* check_command = app.add_subcommand(
      "check-submission", "Run an exported submission in the official Robotarium Python simulator (or, when it is\n"
                          "not installed, DREAM's stand-in), import what it saved and compare it with the run.\n"
                          "Example: dream check-submission exports/go_to_goal --out runs/go_to_goal_check");
  check_command->add_option("export", check_args.export_dir, "The folder dream export wrote")->required();
  check_command->add_option("--out", check_args.out_dir, "Output folder (default runs/<name>_check)");
  check_command->add_option("--run", check_args.run_dir, "The simulated run to compare with (default: the exported one)");
  check_command->add_option("--simulator", check_args.simulator,
                            "robotarium_python_simulator checkout (default $ROBOTARIUM_PYTHON_SIMULATOR)");
  check_command->add_option("--python", check_args.python, "Python with numpy (and what the simulator needs)");
  check_command->add_flag("--standin", check_args.standin, "Use DREAM's stand-in even if the official one is there");
  check_command->add_flag("--require-official", check_args.require_official,
                          "Fail (exit 1) instead of using the stand-in when the official simulator is missing");
  check_command->add_flag("--skip-initialization", check_args.skip_initialization,
                          "Start exactly at the start poses (no start-up drive)");

  SweepArgs sweep_args;
  CLI::App* sweep_command = app.add_subcommand(
      "sweep", "Run an experiment over many seeds and parameter values in parallel (one dream run process per\n"
               "run, --jobs at a time) and tabulate the outcomes in <out>/sweep.csv and sweep.md (docs/sweeps.md).\n"
               "Example: dream sweep config/hrvo_circle.yaml --seeds 1-20 --out sweeps/hrvo_circle");
  sweep_command->add_option("config", sweep_args.config_path, "Run config (YAML) to sweep")->required();
  sweep_command->add_option("--seeds", sweep_args.seeds, "Seeds: 7, 1-20 or 1,4,9-12 (default: the config's seed)");
  sweep_command
      ->add_option("--set", sweep_args.sets,
                   "KEY=V1,V2,...: also sweep this config key (dotted: controller.max_speed_mps,\n"
                   "controller.sensors.0.noise_std); repeat for more keys, every combination runs")
      ->allow_extra_args(false);
  sweep_command->add_option("-j,--jobs", sweep_args.jobs, "Runs at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  sweep_command->add_option("--steps", sweep_args.steps, "Override the config's step limit in every run")
      ->check(StepCount());
  sweep_command->add_option("--out", sweep_args.out_dir, "Sweep folder (its parent must exist)")->required();
  sweep_command->add_option("--timeout", sweep_args.run_timeout_s,
                            "Stop a run still going after this many seconds; it counts as failed")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  // Pictures and videos of a recorded run (docs/rendering.md).
  RenderArgs render_args;
  CLI::App* render_command = app.add_subcommand(
      "render", "Draw a recorded run (simulated or imported from the lab): the arena with trajectories, obstacles,\n"
                "goals and final poses (.png/.svg), a video of the run (.mp4/.gif, needs ffmpeg), or the metrics\n"
                "over time (--plot). --out's extension picks; without --out: trajectories.svg, run.mp4 (--video)\n"
                "or metrics.png (--plot) beside the log.\n"
                "Example: dream render runs/hrvo_circle --out runs/hrvo_circle/run.mp4 --radio-links");
  render_command->add_option("run", render_args.input, "Run folder (its run.lcmlog) or an .lcmlog file")->required();
  render_command->add_option("--out", render_args.out, "Output file: .png, .svg, .mp4 or .gif");
  render_command->add_option("--config", render_args.config_path,
                             "The run's config, for goals, sensors and radio (default: config.yaml beside the log)");
  render_command->add_flag("--video", render_args.video, "Without --out: write run.mp4 beside the log");
  render_command->add_flag("--plot", render_args.plot,
                           "Plot the metrics over time (summary.json's series and the closest approach)");
  render_command->add_option("--metric", render_args.metrics, "Plot only this series (repeat for more; implies --plot)")
      ->allow_extra_args(false);
  render_command->add_flag("--radio-links", render_args.radio_links,
                           "Draw radio broadcasts from sender to the robots that hear it (from the config's radio)");
  render_command->add_flag("--sensor-ranges", render_args.sensor_ranges,
                           "Draw the reach of the movement/obstacle sensors round each robot");
  render_command->add_option("--width", render_args.width_px,
                             "Width in pixels (default 1280 picture, 1000 plot, 720 MP4, 480 GIF)")
      ->check(CLI::Range(160, 8192));
  render_command->add_option("--fps", render_args.fps, "Video frames per second (default 30 MP4, 15 GIF)")
      ->check(CLI::Range(1.0, 120.0));
  render_command->add_option("--speed", render_args.speed, "Simulated seconds per video second")
      ->check(CLI::Range(0.01, 10000.0))
      ->capture_default_str();
  render_command->add_option("--trail", render_args.trail_s, "Seconds of simulated time drawn behind each robot")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();

  // CLI11 would only say "A subcommand is required"; name the unknown word.
  // Options before the subcommand are the global ones only.
  for (int i = 1; i < argc && argv[i][0] == '-'; ++i) {
    const std::string option = argv[i];
    if (option != "-q" && option != "--quiet" && option != "-v" && option != "--verbose" && option != "-h" &&
        option != "--help") {
      std::cerr << "dream: unknown option '" << option << "' before the subcommand; global options are -q, -v, -h"
                << " (dream --help)\n";
      return kExitUsage;
    }
  }
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
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    // One line, like every other failure, and where to read more.
    std::cerr << "dream: " << e.what() << " (" << ParsedCommand(app) << " --help)\n";
    return kExitUsage;
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
    if (*export_command) return RunExport(export_args);
    if (*import_command) return RunImport(import_args);
    if (*replay_command) return RunLabReplay(replay_args);
    if (*compare_command) return RunCompare(compare_args);
    if (*check_command) return RunCheckSubmission(check_args);
    if (*sweep_command) return RunSweep(sweep_args);
    if (*render_command) return RunRender(render_args);
  } catch (const dream::config::ConfigError& e) {
    std::cerr << "dream: " << e.what() << '\n';
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "dream: " << e.what() << '\n';
    return kExitInputError;
  }
  return kExitUsage;
}
