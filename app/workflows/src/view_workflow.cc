#include "dream/workflows/view_workflow.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <thread>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/run_config/run_config.h"
#include "dream/view/frame_json.h"
#include "dream/view/live_view.h"
#include "dream/view/thread_priority.h"
#include "dream/view/view_server.h"
#include "dream/workflows/run_view.h"
#include "dream/workflows/view_replay.h"
#include "dream/workflows/view_video_exports.h"

namespace dream::workflows {
namespace {

void WaitFor(const std::atomic<bool>& stop) {
  while (!stop.load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

}  // namespace

void ViewWorkflow::Serve(const Options& options) const {
  if (options.run.empty()) {
    ServeLive(options);
  } else {
    ServeReplay(options);
  }
}

void ViewWorkflow::ServeLive(const Options& args) const {
  const std::string url = lcm::ResolveLcmUrl(args.lcm_url);
  view::ViewSetup setup;
  if (!args.config_path.empty()) {
    setup = ViewSetupOfConfig(run_config::LoadRunConfigFile(args.config_path), view::ViewSetup::Mode::kLive, url,
                              args.python_runtime_dir);
  }
  setup.mode = view::ViewSetup::Mode::kLive;
  setup.source = url;
  setup.commands_on_request = true;  // on udpm the robots' commands are most of the datagrams: none unless shown
  if (args.fps > 0) setup.frame_rates = view::FrameRates::One(args.fps);
  // Best effort: the runs it watches (on this machine, often) get the cores first.
  view::LowerThisProcesssPriority();
  lcm::LcmBus bus(url);
  view::ViewServer server({args.bind, args.port, false, 8});
  view::LiveView live(bus, server, setup);
  out_ << "dream view: open " << server.url() << " (live: any DREAM run on " << url << "); Ctrl-C to stop" << std::endl;
  while (!args.stop->load()) {
    bus.HandleSubscriptions(100);
    live.TakePageRequests();
  }
  if (live.collector().bad_messages() > 0) {
    spdlog::warn("dream view: {} messages on DREAM_* channels did not decode and were not drawn",
                 live.collector().bad_messages());
  }
}

void ViewWorkflow::ServeReplay(const Options& args) const {
  const ViewReplay replay = ViewReplay::OfRun(args.run, args.config_path, args.python_runtime_dir);
  view::ViewServer server({args.bind, args.port, true, 8});
  server.SetSetup(view::SetupJson(replay.setup));
  server.SetRunData(replay.run_json);
  server.SetVideoExports(VideoExportsOfRun(replay, args.run, args.config_path));
  // Steps as summary.json counts them (the last step's number), with the log's range: its
  // pose frames are one more, step 0's included.
  out_ << "dream view: open " << server.url() << " (replay of " << args.run << ", steps " << replay.first_step << "-"
       << replay.last_step << "); Ctrl-C to stop" << std::endl;
  WaitFor(*args.stop);
}

}  // namespace dream::workflows
