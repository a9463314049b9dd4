#pragma once

#include <atomic>
#include <iostream>
#include <ostream>
#include <string>

namespace dream::workflows {

/// `dream view`: the arena served to a web browser on 127.0.0.1 until Ctrl-C:
/// live, any DREAM run on the LCM bus (view::LiveView), or the replay of a
/// finished run (ViewReplay). Prints the page's address.
class ViewWorkflow {
 public:
  struct Options {
    std::string run;          ///< a run folder or .lcmlog to replay; empty: live from the bus
    std::string lcm_url;      ///< live: empty: $LCM_DEFAULT_URL, else LCM's default
    std::string config_path;  ///< goals, sensors and radio of the run; replay: config.yaml beside the log
    int port = 8077;
    std::string bind = "127.0.0.1";
    int fps = 0;                              ///< live: frames a second to each page at most; 0: FrameRates' defaults
    std::string python_runtime_dir;           ///< a Python controller's goal points (ViewSetupOfConfig)
    const std::atomic<bool>* stop = nullptr;  ///< Ctrl-C: serving ends; required
  };

  explicit ViewWorkflow(std::ostream& out = std::cout) : out_(out) {}

  /// Serves until `options.stop` is set.
  /// @throws std::runtime_error naming the run, config or address that cannot be used.
  void Serve(const Options& options) const;

 private:
  void ServeLive(const Options& options) const;
  void ServeReplay(const Options& options) const;

  std::ostream& out_;
};

}  // namespace dream::workflows
