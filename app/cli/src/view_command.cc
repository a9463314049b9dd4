// dream view (workflows::ViewWorkflow): options.
#include "command_line.h"
#include "commands.h"
#include "dream/process/data_files.h"
#include "dream/view/frame_rates.h"
#include "dream/workflows/view_workflow.h"
#include "shared_options.h"

namespace dream::cli {
namespace {

int ServeView(workflows::ViewWorkflow::Options options) {
  options.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  options.stop = &StopFlag();
  workflows::ViewWorkflow().Serve(options);
  return kExitOk;
}

}  // namespace

void DeclareViewCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<workflows::ViewWorkflow::Options>(
      "view",
      "Watch runs in a web browser: the arena to scale, robots, trails, goals, obstacles, radio,\n"
      "violations where and when they happen, the verdict so far. Served by dream on 127.0.0.1.\n"
      "Live (no RUN): draws any DREAM run on the LCM bus (dream sim, launch, lab-replay, lcm-logplayer).\n"
      "Replay: dream view runs/go_to_goal: the finished run with play, pause, step, scrub and speed.\n"
      "Example: dream view --config config/go_to_goal.yaml   (then open http://127.0.0.1:8077/)",
      ServeView);
  command->add_option("run", args->run, "A run folder (its run.lcmlog) or an .lcmlog file to replay; none: live");
  command->add_option("--lcm-url", args->lcm_url,
                      "Live: LCM URL (default $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");
  command->add_option("--config", args->config_path,
                      "The run's config, for its goals, sensor ranges and radio links (replay: config.yaml\n"
                      "beside the log by default)");
  command->add_option("--port", args->port, "Port of the page (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command
      ->add_option("--fps", args->fps,
                   "Live: frames a second each page gets and draws at most; fewer cost the machine less\n"
                   "(default: 30; 10 while the run goes faster than twice real time, 5 beyond ten times)")
      ->check(CLI::Range(1, view::FrameRates::kMax));
  command
      ->add_option("--bind", args->bind,
                   "Address to listen on; 127.0.0.1 (the default) is this machine only,\n"
                   "0.0.0.0 exposes the page to the network on purpose")
      ->capture_default_str();
}

}  // namespace dream::cli
