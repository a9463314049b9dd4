#include "dream/workflows/run_view.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

#include "dream/agent_host/controller_factory.h"
#include "dream/session/render_overlays.h"
#include "dream/view/frame_json.h"
#include "dream/workflows/kind_step_metrics.h"
#include "dream/workflows/view_replay.h"

namespace dream::workflows {

namespace {

/// The goals a kind declares when its builder drew none (a Python controller's goal_points()): a
/// finished run's from its summary.json, else what the kind computes from the config, once, before
/// the view starts (ControllerKind::goals_before_run; nothing for a kind without them).
void AddDeclaredGoalsOfKind(const run_config::RunConfig& config, const std::string& python_runtime_dir,
                            const std::string& run_dir, render::ArenaOverlays* overlays) {
  if (!overlays->goals_m.empty()) return;
  if (!run_dir.empty() && session::AddDeclaredGoalsOfRun(run_dir + "/summary.json", overlays)) return;
  try {
    session::AddKindGoals(config, python_runtime_dir, overlays);
  } catch (const std::exception& e) {
    spdlog::warn("dream view: drawing without the controller's goal points: {}", e.what());
  }
}

/// The kind's metrics step by step, for the plots (a warning, and none, when the config's kind cannot tell);
/// live, with the kind's own metrics computed in `python_runtime_dir`'s runtime (a Python controller's
/// metrics(); a replay has them from summary.json).
std::function<std::unique_ptr<view::StepMetrics>()> KindMetricsOf(const run_config::RunConfig& config,
                                                                  const std::string& python_runtime_dir) {
  try {
    auto factory = std::make_shared<const agent_host::ControllerFactory>(config);
    auto own_config = std::make_shared<const run_config::RunConfig>(config);
    return [factory, own_config, python_runtime_dir]() -> std::unique_ptr<view::StepMetrics> {
      return std::make_unique<KindStepMetrics>(*factory, own_config.get(), python_runtime_dir);
    };
  } catch (const std::exception& e) {
    spdlog::warn("dream view: no metrics plotted: {}", e.what());
    return nullptr;
  }
}

}  // namespace

view::ViewSetup ViewSetupOfConfig(const run_config::RunConfig& config, view::ViewSetup::Mode mode,
                                  const std::string& source, const std::string& python_runtime_dir,
                                  const std::string& run_dir) {
  view::ViewSetup setup;
  setup.mode = mode;
  setup.world = config.world;
  setup.source = source;
  try {
    setup.overlays = session::ArenaOverlaysFromConfig(config);
  } catch (const std::exception& e) {
    // Goals and radio are a nicety: the run itself is drawn from the bus.
    spdlog::warn("dream view: drawing without the config's goals and radio: {}", e.what());
  }
  AddDeclaredGoalsOfKind(config, python_runtime_dir, run_dir, &setup.overlays);
  setup.overlays.run_name = config.name;
  setup.metrics = KindMetricsOf(config, mode == view::ViewSetup::Mode::kLive ? python_runtime_dir : std::string());
  return setup;
}

RunView::RunView(lcm::LcmInterface& bus, const run_config::RunConfig& config, const std::string& bind, int port,
                 int frames_per_second, const std::string& python_runtime_dir, const std::atomic<bool>& stop)
    : server_(view::ViewServer::Options{bind, port, false, 8}), python_runtime_dir_(python_runtime_dir), stop_(stop) {
  view::ViewSetup setup = ViewSetupOfConfig(config, view::ViewSetup::Mode::kLive, config.source, python_runtime_dir_);
  if (frames_per_second > 0) setup.frame_rates = view::FrameRates::One(frames_per_second);
  live_ = std::make_unique<view::LiveView>(bus, server_, std::move(setup));
  std::cout << "dream view: open " << server_.url() << " to watch the run ";
  if (config.sim.pace > 0) {
    std::cout << "(paced to " << config.sim.pace << "x real time)" << std::endl;
  } else {
    std::cout << "(unpaced: as fast as it goes)" << std::endl;
  }
}

namespace {

std::string FormatSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g s", seconds);
  return text;
}

/// Waits, a tenth of a second at a time, until `done` or Ctrl-C or the
/// deadline (none when `seconds` <= 0); returns whether `done`.
template <typename Done>
bool WaitUntil(Done done, double seconds, const std::atomic<bool>& stop) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (stop.load() || (seconds > 0 && std::chrono::steady_clock::now() >= deadline)) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return true;
}

}  // namespace

bool RunView::WaitForBrowser(double timeout_s) {
  std::cout << "dream view: waiting for a browser at " << server_.url() << " before step 0 (Ctrl-C to stop"
            << (timeout_s > 0 ? ", the run starts anyway after " + FormatSeconds(timeout_s) : std::string()) << ")"
            << std::endl;
  if (WaitUntil([this] { return server_.clients() > 0; }, timeout_s, stop_)) {
    std::cout << "dream view: a browser is watching: the run starts" << std::endl;
    return true;
  }
  if (stop_.load()) return false;
  std::cout << "dream view: no browser within " << FormatSeconds(timeout_s) << ": the run starts" << std::endl;
  return true;
}

void RunView::ServeReplayOf(const std::string& run_dir) {
  try {
    live_->ShowEndOf(run_dir + "/run.lcmlog");
  } catch (const std::exception& e) {
    spdlog::warn("dream view: the page shows the run without its last step: {}", e.what());
  }
  live_.reset();  // its last frame is out; no live frame may follow the replay's setup
  try {
    const ViewReplay replay = ViewReplay::OfRun(run_dir, "", python_runtime_dir_);
    server_.ServeReplay(view::SetupJson(replay.setup), replay.run_json);
    std::cout << "dream view: the run is over; " << server_.url() << " replays it. Later: dream view " << run_dir
              << std::endl;
  } catch (const std::exception& e) {
    spdlog::warn("dream view: the page keeps the run's live end, not its replay: {}", e.what());
  }
}

RunView::Keep RunView::Keep::Parse(const std::string& text) {
  Keep keep;
  if (text == "watched") return keep;
  if (text == "ctrl-c") {
    keep.until = Until::kCtrlC;
    return keep;
  }
  size_t used = 0;
  double seconds = -1.0;
  try {
    seconds = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(seconds) || seconds < 0) {
    throw std::runtime_error(
        "--view-keep " + text +
        ": not watched, ctrl-c or a number of seconds (0 or more) to serve the page after the run");
  }
  keep.until = Until::kSeconds;
  keep.seconds = seconds;
  return keep;
}

void RunView::KeepServing(const Keep& keep) {
  if (stop_.load()) return;  // the run was interrupted: the user is leaving
  switch (keep.until) {
    case Keep::Until::kWatched:
      if (server_.clients() == 0) return;
      std::cout << "dream view: a browser is watching: serving until Ctrl-C (--view-keep 0 to stop at the run's end)"
                << std::endl;
      WaitUntil([] { return false; }, 0, stop_);
      return;
    case Keep::Until::kCtrlC:
      std::cout << "dream view: serving until Ctrl-C" << std::endl;
      WaitUntil([] { return false; }, 0, stop_);
      return;
    case Keep::Until::kSeconds:
      if (keep.seconds <= 0) return;
      std::cout << "dream view: serving for " << FormatSeconds(keep.seconds) << " (Ctrl-C to stop sooner)" << std::endl;
      WaitUntil([] { return false; }, keep.seconds, stop_);
      return;
  }
}

}  // namespace dream::workflows
