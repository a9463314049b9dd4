// dream run and dream sim (workflows::RunWorkflow): options and exit codes.
#include <stdexcept>

#include "command_line.h"
#include "commands.h"
#include "dream/process/data_files.h"
#include "dream/view/frame_rates.h"
#include "dream/workflows/run_workflow.h"
#include "script_command.h"
#include "shared_options.h"

namespace dream::cli {

namespace {

/// What dream run and dream sim take from this program: the Python runtime
/// beside it and the stop flag Ctrl-C sets.
workflows::RunWorkflow Workflow() { return {process::DataFiles::PythonRuntimeDir(), StopFlag()}; }

}  // namespace

int RunEmbedded(const RunArgs& args) {
  if (IsScriptPath(args.config_path) || !ScriptOfConfig(args.config_path).empty()) {
    return RunScript(args, {});
  }
  if (args.private_bus && !args.lcm_url.empty()) {
    throw std::invalid_argument("--private-bus and --lcm-url both choose the bus; give one");
  }
  return Workflow().RunEmbedded(args);
}

int RunSimOnly(const RunArgs& args) {
  if (IsScriptPath(args.config_path) || !ScriptOfConfig(args.config_path).empty()) {
    throw std::invalid_argument("dream sim " + args.config_path +
                                ": the world of a Robotarium script's run starts where the script's Robotarium(...) "
                                "leaves the robots, so only `dream run " +
                                args.config_path + "` can start it (docs/robotarium-scripts.md)");
  }
  return Workflow().RunSimOnly(args);
}

void DeclareRunCommand(CommandLine& line) {
  const auto [command, args] =
      AddRunCommand(line, "run",
                    "Run an experiment in one process: the simulator and every robot's agent on one bus.\n"
                    "Example: dream run config/go_to_goal.yaml --seed 7 --set controller.max_speed_mps=0.1\n"
                    "An unmodified Robotarium script: dream run my_script.py (docs/robotarium-scripts.md)\n"
                    "Watch it: dream run config/go_to_goal.yaml --view (then open http://127.0.0.1:8077/)",
                    RunEmbedded, "LCM URL (default memq://, in-process)");
  command->add_flag("--private-bus", args->private_bus,
                    "A script's run: its processes talk on a udpm group and port of their own, drawn at random\n"
                    "(dream sweep's runs use it); a config's run is in one process, on memq://, anyway");
  CLI::Option* const view =
      command->add_flag("--view", args->view,
                        "Serve the live arena while the run runs (dream view; paced to real time unless --pace), then\n"
                        "the finished run as a replay at the same URL (--view-keep)");
  command->add_option("--view-port", args->view_port, "Port of --view's page (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command
      ->add_option("--view-fps", args->view_fps,
                   "Frames a second --view's page gets and draws at most; fewer cost the machine less\n"
                   "(default: 30; 10 while the run goes faster than twice real time, 5 beyond ten times)")
      ->check(CLI::Range(1, view::FrameRates::kMax));
  command
      ->add_flag("--view-wait", args->view_wait,
                 "With --view: take no step before a browser has the page open (Ctrl-C to give up)")
      ->needs(view);
  command
      ->add_option("--view-wait-timeout", args->view_wait_timeout_s,
                   "With --view-wait: start the run anyway after this many seconds (default 0: wait until\n"
                   "a browser comes or Ctrl-C)")
      ->check(CLI::Range(0.0, 1e6))
      ->needs(view);
  command
      ->add_option("--view-keep", args->view_keep,
                   "With --view: how long the page serves the finished run (a replay, same URL) after the\n"
                   "run: watched (until Ctrl-C if a browser is connected at the end, else not at all),\n"
                   "ctrl-c (until Ctrl-C), or a number of seconds (0: stop with the run)")
      ->capture_default_str()
      ->needs(view);
  command
      ->add_option("--view-bind", args->view_bind,
                   "Address --view listens on; 127.0.0.1 (the default) is this machine only,\n"
                   "0.0.0.0 exposes the page to the network on purpose")
      ->capture_default_str();
}

void DeclareSimCommand(CommandLine& line) {
  AddRunCommand(line, "sim",
                "Run only the simulator; agents run elsewhere (dream agent) on the same LCM URL.\n"
                "Example: dream sim config/go_to_goal.yaml --lcm-url 'udpm://239.255.76.67:7667?ttl=0'",
                RunSimOnly, "LCM URL (default $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");
}

}  // namespace dream::cli
