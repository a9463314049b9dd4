#include <spdlog/spdlog.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "command_line.h"
#include "commands.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/view/frame_json.h"
#include "dream/view/live_view.h"
#include "dream/view/thread_priority.h"
#include "dream/view/view_server.h"
#include "run_view.h"
#include "shared_options.h"
#include "view_replay.h"

namespace dream::cli {
namespace {

struct ViewArgs {
  std::string run;          ///< a run folder or .lcmlog to replay; empty: live from the bus
  std::string lcm_url;      ///< live: empty: $LCM_DEFAULT_URL, else LCM's default
  std::string config_path;  ///< goals, sensors and radio of the run; replay: config.yaml beside the log
  int port = 8077;
  std::string bind = "127.0.0.1";
  int fps =
      0;  ///< live: frames a second to each page at most; 0: FrameRates' defaults (30, fewer while the run is fast)
};

void WaitForCtrlC() {
  while (!StopFlag().load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

int RunLiveView(const ViewArgs& args) {
  const std::string url = lcm::ResolveLcmUrl(args.lcm_url);
  view::ViewSetup setup;
  if (!args.config_path.empty()) {
    setup = ViewSetupOfConfig(run_config::LoadRunConfigFile(args.config_path), view::ViewSetup::Mode::kLive, url);
  }
  setup.mode = view::ViewSetup::Mode::kLive;
  setup.source = url;
  if (args.fps > 0) setup.frame_rates = view::FrameRates::One(args.fps);
  // Best effort: the runs it watches (on this machine, often) get the cores first.
  view::LowerThisProcesssPriority();
  lcm::LcmBus bus(url);
  view::ViewServer server({args.bind, args.port, false, 8});
  view::LiveView live(bus, server, setup);
  std::cout << "dream view: open " << server.url() << " (live: any DREAM run on " << url << "); Ctrl-C to stop"
            << std::endl;
  while (!StopFlag().load()) bus.HandleSubscriptions(100);
  if (live.collector().bad_messages() > 0) {
    spdlog::warn("dream view: {} messages on DREAM_* channels did not decode and were not drawn",
                 live.collector().bad_messages());
  }
  return kExitOk;
}

int RunReplayView(const ViewArgs& args) {
  const ViewReplay replay = ViewReplay::OfRun(args.run, args.config_path);
  view::ViewServer server({args.bind, args.port, true, 8});
  server.SetSetup(view::SetupJson(replay.setup));
  server.SetRunData(replay.run_json);
  std::cout << "dream view: open " << server.url() << " (replay of " << args.run << ", " << replay.steps
            << " steps); Ctrl-C to stop" << std::endl;
  WaitForCtrlC();
  return kExitOk;
}

}  // namespace

void DeclareViewCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<ViewArgs>(
      "view",
      "Watch runs in a web browser: the arena to scale, robots, trails, goals, obstacles, radio,\n"
      "violations where and when they happen, the verdict so far. Served by dream on 127.0.0.1.\n"
      "Live (no RUN): draws any DREAM run on the LCM bus (dream sim, launch, lab-replay, lcm-logplayer).\n"
      "Replay: dream view runs/go_to_goal: the finished run with play, pause, step, scrub and speed.\n"
      "Example: dream view --config config/go_to_goal.yaml   (then open http://127.0.0.1:8077/)",
      std::function<int(const ViewArgs&)>(
          [](const ViewArgs& a) { return a.run.empty() ? RunLiveView(a) : RunReplayView(a); }));
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
