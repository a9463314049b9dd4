#include "run_view.h"

#include <spdlog/spdlog.h>

#include <exception>
#include <iostream>

#include "dream/session/render_overlays.h"

namespace dream::cli {

view::ViewSetup ViewSetupOfConfig(const run_config::RunConfig& config, view::ViewSetup::Mode mode,
                                  const std::string& source) {
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
  setup.overlays.run_name = config.name;
  return setup;
}

RunView::RunView(lcm::LcmInterface& bus, const run_config::RunConfig& config, const std::string& bind, int port)
    : server_(view::ViewServer::Options{bind, port, false, 8}) {
  live_ = std::make_unique<view::LiveView>(bus, server_,
                                           ViewSetupOfConfig(config, view::ViewSetup::Mode::kLive, config.source));
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
