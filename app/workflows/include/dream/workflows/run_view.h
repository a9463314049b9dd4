#pragma once

#include <atomic>
#include <memory>
#include <string>

#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/view/live_view.h"
#include "dream/view/view_server.h"

namespace dream::workflows {

/// `dream run --view`: the live arena served while the run runs in this
/// process, then the finished run as a replay at the same URL. Its bus
/// handler only keeps the newest frame; the simulator's loop drives it, the
/// view never waits for a browser (except before step 0, when asked:
/// WaitForBrowser).
class RunView {
 public:
  /// Listens on `bind`:`port` and prints the page's address.
  /// @throws std::runtime_error when it cannot listen there.
  /// `frames_per_second` 0: FrameRates' defaults (30, fewer while the run is
  /// fast); `python_runtime_dir`: a Python controller's goal points
  /// (ViewSetupOfConfig); `stop` (Ctrl-C) ends every wait.
  RunView(lcm::LcmInterface& bus, const run_config::RunConfig& config, const std::string& bind, int port,
          int frames_per_second, const std::string& python_runtime_dir, const std::atomic<bool>& stop);
  /// --view-wait: waits until a browser has the page open, so the user sees
  /// step 0. Returns false when Ctrl-C came first (`stop`), true when a
  /// browser connected or `timeout_s` (> 0; 0: none) passed, which it says.
  bool WaitForBrowser(double timeout_s);
  /// The run is over: shows its end (its last step, from `run_dir`'s log: the
  /// last messages of a memq run are never handled), then serves it as the
  /// replay `dream view run_dir` gives, at the same URL: the pages open now
  /// load it and show its last step with summary.json's verdict, goal and
  /// metrics. A run folder that cannot be replayed is only logged (the page
  /// keeps the live end). Prints the replay command.
  void ServeReplayOf(const std::string& run_dir);
  /// How long the page is served after the run (--view-keep).
  struct Keep {
    enum class Until { kWatched, kCtrlC, kSeconds };
    Until until = Until::kWatched;  ///< kWatched: until Ctrl-C if a browser is connected now, else not at all
    double seconds = 0.0;           ///< kSeconds: this long, or less at Ctrl-C
    /// "watched", "ctrl-c" or seconds (0: stop at once).
    /// @throws std::runtime_error naming --view-keep and the value.
    static Keep Parse(const std::string& text);
  };
  /// Serves the page as `keep` says, saying so and how to stop.
  void KeepServing(const Keep& keep);

 private:
  view::ViewServer server_;
  std::unique_ptr<view::LiveView> live_;
  std::string python_runtime_dir_;
  const std::atomic<bool>& stop_;
};

/// The view's setup from a run config: its arena and time step, and what it
/// adds (goals, sensor reaches, who hears whom), read as dream render reads
/// them; without them (the config's controller cannot tell) a warning, and
/// the view draws the run without. A Python controller's goal_points() come
/// from `run_dir`'s summary.json when given (a replay), else are computed
/// from the config once, here, with the runtime in `python_runtime_dir`.
view::ViewSetup ViewSetupOfConfig(const run_config::RunConfig& config, view::ViewSetup::Mode mode,
                                  const std::string& source, const std::string& python_runtime_dir,
                                  const std::string& run_dir = "");

}  // namespace dream::workflows
