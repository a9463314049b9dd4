#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "dream/config/config_node.h"
#include "dream/config/config_error.h"
#include "dream/config/controller_config.h"

namespace dream::config_overrides {

/// A run config file with the command line's --seed N and --set KEY=VALUE
/// applied (dream run, sim, launch and dream-agent), and the text its run
/// folder keeps as config.yaml, so that folder alone reruns the same run.
///
/// --set has dream sweep's syntax and messages (SweepParameter,
/// ApplyConfigOverride), with one value per key.
class OverriddenConfig {
 public:
  /// Reads `path` and applies `seed` (when >= 0), then each "KEY=VALUE" of
  /// `sets` in order.
  /// @throws config::ConfigError when the file is missing or not YAML;
  ///         std::invalid_argument naming the --set and its key otherwise.
  OverriddenConfig(const std::string& path, long long seed, const std::vector<std::string>& sets);

  /// The config's root with the overrides applied (or the file as read).
  config::ConfigNode Document() const;

  /// The controller's part only (what an agent process needs; no world):
  /// @throws config::ConfigError as Load() does, for those keys.
  config::ControllerConfig LoadController() const;

  /// `load(Document())`: the checked config, e.g. the whole run with
  /// `LoadWith(&run_config::LoadRunConfig)` (this library does not link the
  /// world, which dream-agent leaves out). @throws config::ConfigError
  /// "file:line: key: ..." which, for a config with overrides, also names them
  /// (the value at that line may be one the command line gave).
  template <typename Config>
  Config LoadWith(Config (*load)(const config::ConfigNode&)) const {
    try {
      return load(Document());
    } catch (const config::ConfigError& e) {
      throw config::ConfigError(Noted(e.what()));
    }
  }

  /// The config as its run folder keeps it (give it to
  /// run_config::RunFolderConfigText): without overrides the file's bytes
  /// (comments and all); with them the overridden YAML under a header naming
  /// the file and the options.
  std::string Text() const;

  /// "--seed 3 --set controller.max_speed_mps=0.1", empty without overrides.
  std::string OptionsText() const;

  /// `message` with " (with --set ...)" appended when there are overrides: for
  /// the errors of later checks (the controller section), whose file:line may
  /// hold a value the command line replaced.
  std::string Noted(const std::string& message) const;

 private:
  std::string path_;
  std::string text_;                    // the file's bytes
  YAML::Node root_;                     // the file with the overrides applied
  std::vector<std::string> overrides_;  // "--seed 3", "--set KEY=VALUE", in order
};

}  // namespace dream::config_overrides
