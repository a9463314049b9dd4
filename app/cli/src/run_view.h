#pragma once

#include <memory>
#include <string>

#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/view/live_view.h"
#include "dream/view/view_server.h"

namespace dream::cli {

/// `dream run --view`: the live arena served while the run runs in this
/// process. Its bus handler only keeps the newest frame; the simulator's
/// loop drives it, the view never waits for a browser.
class RunView {
 public:
  /// Listens on `bind`:`port` and prints the page's address.
  /// @throws std::runtime_error when it cannot listen there.
  RunView(lcm::LcmInterface& bus, const run_config::RunConfig& config, const std::string& bind, int port,
          int frames_per_second = 0);  ///< 0: FrameRates' defaults (30, fewer while the run is fast)
  /// Shows the run's end, from its log in `run_dir` (the last messages of a
  /// memq run are never handled); a log that cannot be read is only logged.
  void ShowEndOf(const std::string& run_dir);

 private:
  view::ViewServer server_;
  std::unique_ptr<view::LiveView> live_;
};

/// The view's setup from a run config: its arena and time step, and what it
/// adds (goals, sensor reaches, who hears whom), read as dream render reads
/// them; without them (the config's controller cannot tell) a warning, and
/// the view draws the run without. A Python controller's goal_points() come
/// from `run_dir`'s summary.json when given (a replay), else are computed
/// from the config once, here.
view::ViewSetup ViewSetupOfConfig(const run_config::RunConfig& config, view::ViewSetup::Mode mode,
                                  const std::string& source, const std::string& run_dir = "");

}  // namespace dream::cli
