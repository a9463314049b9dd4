#pragma once

#include <array>
#include <atomic>
#include <string>
#include <vector>

#include "dream/lcm/lcm_interface.h"
#include "dream/run_config/run_config.h"
#include "dream/session/run_result.h"
#include "dream/session/run_session.h"
#include "dream/workflows/run_options.h"

namespace dream::workflows {

/// `dream run SCRIPT.py`'s world (docs/robotarium-scripts.md): an unmodified
/// Robotarium script, started by the command line with DREAM's rps first on
/// its path, says at `Robotarium(...)` how many robots it drives and where
/// the official start-up drive left them (one JSON line, ScriptHello); this
/// builds the run from that (a run config for those robots and poses, the
/// command's --seed and --set applied) and runs the world for it, the script
/// being the one agent of every robot, recorded, judged and reported as any run.
class ScriptRunWorkflow {
 public:
  /// What the script says when it makes its Robotarium.
  struct Hello {
    int robots = 0;
    std::vector<std::array<double, 3>> initial_poses;  ///< where the start-up drive ended
    long long startup_steps = 0;                       ///< the drive's steps, in the script's debug() count
  };

  /// The most a hello line may hold: 50 robots' poses need far less.
  static constexpr size_t kMaxHelloBytes = 64 * 1024;

  struct Options {
    std::string script_path;  ///< the script, as given
    /// A run config naming the script (`script:`: a sweep's run, or a script
    /// run's config.yaml rerun): the run keeps its keys, the script's hello
    /// giving its robots and initial_poses. Empty: ConfigText's defaults.
    std::string base_config_path;
    long long seed = 1;  ///< the script's and the world's seed
    std::vector<std::string> sets;
    long long steps = 0;             ///< --steps; 0: until the script ends (kDefaultSteps at most)
    std::string python_runtime_dir;  ///< DataFiles::PythonRuntimeDir(): its rps_dream/ folder
    session::RunSession::Options session;
    /// The command's --pace and --view options (view, view_*), as `dream run CONFIG` takes them.
    RunOptions watch;
    /// Ctrl-C alone (session.stop is also set when the script has ended): what
    /// ends --view's waits and its serving after the run. Null: never.
    const std::atomic<bool>* interrupted = nullptr;
  };

  /// Where DREAM's rps writes the script's last at_pose/at_position check in
  /// the run folder when the script ends the run: the goal the run is judged
  /// by unless its config gives one (`controller.goal_points`/`goal_poses`;
  /// docs/robotarium-scripts.md#the-goal). Run names it as the config's
  /// `controller.goal_record`, so the judge (robotarium_script.py) reads it.
  static constexpr const char* kGoalRecordName = "script_goal.json";

  /// A script run's step limit unless --steps says otherwise (about 9 hours simulated).
  static constexpr long long kDefaultSteps = 1000000;

  /// Whether `path` names a Robotarium script (a .py file) rather than a run config.
  static bool IsScript(const std::string& path);

  /// The base config of a sweep of the script, checked as a run config
  /// (BaseConfigText): what `dream sweep SCRIPT.py` plans from.
  static run_config::RunConfig BaseConfig(const std::string& script_path, const std::string& python_runtime_dir);

  /// The run's name: the script's file name without .py, every character a
  /// run name cannot hold (letters, digits, _ - .) replaced by _.
  static std::string RunName(const std::string& script_path);

  /// The hello line, checked. @throws std::runtime_error naming the field and
  /// the bad value (robots 1..50, one finite [x, y, theta] per robot).
  static Hello ParseHello(const std::string& line);

  /// The run config (YAML) of `hello`'s run, before --seed and --set;
  /// `goal_record` ("": none) its controller.goal_record (kGoalRecordName in the run folder).
  static std::string ConfigText(const Hello& hello, const Options& options, const std::string& goal_record = "");

  /// What a sweep of the script starts from (`dream sweep SCRIPT.py`): ConfigText
  /// for one robot at the origin, a placeholder the script's own Robotarium(...)
  /// replaces in every run (WithHello).
  static std::string BaseConfigText(const std::string& script_path, const std::string& python_runtime_dir);

  /// The text of the config at `base_path` (which names the script) with
  /// `hello`'s robots and start poses, options.seed, options.steps when > 0,
  /// and `goal_record` as controller.goal_record when given.
  /// @throws config::ConfigError naming the file when it is not YAML.
  static std::string WithHello(const std::string& base_path, const Hello& hello, const Options& options,
                               const std::string& goal_record = "");

  explicit ScriptRunWorkflow(Options options) : options_(std::move(options)) {}

  /// Writes the config into `run_dir` (robotarium_script.yaml), loads it with
  /// the overrides and runs the world on `lcm` until the script ends the run
  /// (every robot done), Options::session.stop is set, or the step limit.
  /// @throws config::ConfigError naming the file, line and key (a --set's too).
  session::RunResult Run(const Hello& hello, const std::string& run_dir, lcm::LcmInterface& lcm) const;
  /// The same on a bus of its own, opened on `url` (BusUrl's).
  session::RunResult Run(const Hello& hello, const std::string& run_dir, const std::string& url) const;

  /// The URL the script's world and the script share: a private udpm group
  /// and port when `private_bus` (a sweep's runs at once never hear each
  /// other), else `lcm_url` when given, else $LCM_DEFAULT_URL, else LCM's
  /// default (lcm::ResolveLcmUrl).
  /// @throws std::invalid_argument naming a URL without "provider://".
  static std::string BusUrl(const std::string& lcm_url, bool private_bus = false);

 private:
  Options options_;
};

}  // namespace dream::workflows
