#include "run_view.h"

#include <spdlog/spdlog.h>

#include <exception>
#include <iostream>
#include <utility>

#include "data_files.h"
#include "dream/session/render_overlays.h"

namespace dream::cli {

namespace {

/// A Python controller's goal_points(), when the kind drew no goals: a finished run's from its
/// summary.json, else computed from the config, once, before the view starts (a short-lived
/// python3, as for its metrics; nothing for other kinds).
void AddPythonControllerGoals(const run_config::RunConfig& config, const std::string& run_dir,
                              render::ArenaOverlays* overlays) {
  if (!overlays->goals_m.empty()) return;
  if (!run_dir.empty() && session::AddDeclaredGoalsOfRun(run_dir + "/summary.json", overlays)) return;
  try {
    session::AddPythonGoals(config, DataFiles::PythonRuntimeDir(), overlays);
  } catch (const std::exception& e) {
    spdlog::warn("dream view: drawing without the controller's goal points: {}", e.what());
  }
}

}  // namespace

view::ViewSetup ViewSetupOfConfig(const run_config::RunConfig& config, view::ViewSetup::Mode mode,
                                  const std::string& source, const std::string& run_dir) {
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
  AddPythonControllerGoals(config, run_dir, &setup.overlays);
  setup.overlays.run_name = config.name;
  return setup;
}

RunView::RunView(lcm::LcmInterface& bus, const run_config::RunConfig& config, const std::string& bind, int port,
                 int frames_per_second)
    : server_(view::ViewServer::Options{bind, port, false, 8}) {
  view::ViewSetup setup = ViewSetupOfConfig(config, view::ViewSetup::Mode::kLive, config.source);
  if (frames_per_second > 0) setup.frame_rates = view::FrameRates::One(frames_per_second);
  live_ = std::make_unique<view::LiveView>(bus, server_, std::move(setup));
  std::cout << "dream view: open " << server_.url() << " to watch the run ";
  if (config.sim.pace > 0) {
    std::cout << "(paced to " << config.sim.pace << "x real time)" << std::endl;
  } else {
    std::cout << "(unpaced: as fast as it goes)" << std::endl;
  }
}

void RunView::ShowEndOf(const std::string& run_dir) {
  try {
    live_->ShowEndOf(run_dir + "/run.lcmlog");
  } catch (const std::exception& e) {
    spdlog::warn("dream view: the page shows the run without its last step: {}", e.what());
  }
}

}  // namespace dream::cli
