#pragma once

#include <string>
#include <vector>

namespace dream::workflows {

/// What a command that runs an experiment (run, sim, launch; sweep's base
/// config) is asked, as typed: the config, its overrides and where the run
/// goes, and for `dream run --view` the live page.
struct RunOptions {
  std::string config_path;
  std::string out_dir;            ///< empty: runs/<name>, or runs/<name>_2, ... when that holds a run
  bool overwrite = false;         ///< replace a run already in the output folder
  long long seed = -1;            ///< --seed; < 0: the config's
  std::vector<std::string> sets;  ///< --set KEY=VALUE each, applied in order
  std::string lcm_url;            ///< empty: memq:// for run, else LCM_DEFAULT_URL
  long long steps = 0;            ///< 0: the config's
  std::string mode;               ///< empty: the config's
  bool all_steps = false;         ///< run every step even when all robots report done
  /// --pace: simulated seconds per wall second; 0: unpaced; < 0 (not given): unpaced, 1 with --view
  double pace = -1.0;
  /// dream run --private-bus: a script run's processes talk on a udpm group
  /// and port of their own, drawn at random (what dream sweep's runs use, so
  /// runs at once never hear each other); a config run is on memq:// anyway.
  bool private_bus = false;
  bool view = false;                    ///< dream run --view: serve the live arena (dream view) while it runs
  int view_port = 8077;                 ///< --view-port
  std::string view_bind = "127.0.0.1";  ///< --view-bind
  int view_fps = 0;        ///< --view-fps: frames a second to the page at most; 0: 30, or 10 while the run is fast
  bool view_wait = false;  ///< --view-wait: no step 0 before a browser has the page open
  double view_wait_timeout_s = 0.0;   ///< --view-wait-timeout: start anyway after this long; 0: wait until Ctrl-C
  std::string view_keep = "watched";  ///< --view-keep: how long the replay is served after the run (RunView::Keep)
};

}  // namespace dream::workflows
