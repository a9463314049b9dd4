#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dream/config/config_node.h"

namespace dream::config {

/// The part of a run config that agents need: which run, how many robots,
/// the seed of every noise source, the `controller:` section and the plugins
/// that add controller kinds. Read without the world's keys, so an agent
/// process never loads the simulator's library nor generates initial poses
/// (RunConfig, the whole run, is one of these plus the world).
struct ControllerConfig {
  std::string source;  ///< the file it came from (for messages)
  std::string name;    ///< run name; default output folder runs/<name>
  uint64_t seed = 1;   ///< seeds initial poses and every noise source
  int num_robots = 0;  ///< 1..kMaxRobots (the Robotarium simulator's), 1..kMaxRobotsSimOnly with sim_only
  /// `sim_only: true`: a run declared for simulation only, which may have up to
  /// kMaxRobotsSimOnly robots and which nothing sends to the lab (dream export,
  /// check-submission and import refuse it).
  bool sim_only = false;
  ConfigNode sim_only_node;  ///< the `sim_only:` entry, for errors naming its line (undefined without one)
  ConfigNode controller;     ///< the `controller:` section, read by the agents' factory
  /// `plugins:` shared libraries that add controller kinds, as absolute
  /// paths (relative ones are relative to `plugin_dir:`, by default the
  /// config file's folder). The agents' factory loads them.
  std::vector<std::string> plugins;
  std::vector<ConfigNode> plugin_nodes;  ///< the `plugins:` entries, for errors naming them

  /// The Robotarium simulator's robot limit (robotarium::RobotariumConstants, checked
  /// equal where both are seen, in run_config.cc).
  static constexpr int kMaxRobots = 50;
  /// What the lab runs at most, for the message.
  static constexpr int kMaxRobotsOnHardware = 20;
  /// With `sim_only: true`: what one bus message may carry
  /// (lcm::MessageLimits::kRobots, checked equal in sim/node's sim_node.cc).
  static constexpr int kMaxRobotsSimOnly = 128;

  /// Why this run may not go to the lab, as "<file>:<line>: sim_only: true — ...
  /// remove `sim_only` (and use at most 20 robots) to <action>"; empty when it
  /// may (not sim_only). `action` says what was refused ("export it").
  std::string LabRefusal(const std::string& action) const;
};

/// Reads and checks `name`, `seed`, `sim_only`, `robots`, `controller` and
/// `plugins` / `plugin_dir` of a run config's root; other keys are left to
/// LoadRunConfig. @throws ConfigError naming file, line, key and value.
ControllerConfig LoadControllerConfig(const ConfigNode& root);

/// The folder relative plugin paths start from: `plugin_dir:` (absolute, so a
/// copy of the config elsewhere still finds them), else the config's folder.
std::filesystem::path PluginBaseDir(const ConfigNode& root);

/// A file a config names (`node`'s text) that its run folder keeps a copy of
/// at the same relative path beside config.yaml (a Python controller's
/// module, a realism file): an absolute path as it is, a relative one taken
/// from the config's folder, which it may not leave (`what` names the file in
/// that error). Not checked for existence. @throws ConfigError.
std::filesystem::path FileBesideConfig(const ConfigNode& node, const std::string& what);

}  // namespace dream::config
