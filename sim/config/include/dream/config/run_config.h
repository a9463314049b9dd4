#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dream/config/config_node.h"
#include "dream/sim/pose2.h"
#include "dream/sim/realism_params.h"
#include "dream/sim/rectangle_obstacle_spec.h"
#include "dream/sim/sim_node_options.h"
#include "dream/sim/world_params.h"

namespace dream::config {

/// A whole run as described by one YAML file (see config/README.md for every
/// key). Initial poses are resolved here: from the file, or generated
/// collision-free from the seed, so every process of a run sees the same.
/// Either way no robot starts touching another or a virtual obstacle (where
/// the obstacle is at step 0).
struct RunConfig {
  std::string source;            ///< the file it came from (for messages)
  std::string name;              ///< run name; default output folder runs/<name>
  uint64_t seed = 1;             ///< seeds initial poses and every noise source
  int num_robots = 0;            ///< 1..50, as the Robotarium simulator allows
  sim::SimNodeOptions sim;       ///< pacing, timeouts, step limit
  sim::WorldParams world;        ///< Robotarium V2 constants (not configurable)
  /// `world.realism:` (a preset name, or a map of models); Ideal(), the
  /// default, is the official simulator (no sim::RealisticWorld).
  sim::RealismParams realism;
  std::vector<sim::Pose2> initial_poses;
  std::vector<sim::RectangleObstacleSpec> obstacles;
  ConfigNode controller;         ///< the `controller:` section, read by the agents' factory
  /// `plugins:` shared libraries that add controller kinds, as absolute
  /// paths (relative ones are relative to `plugin_dir:`, by default the
  /// config file's folder). The agents' factory loads them.
  std::vector<std::string> plugins;
  std::vector<ConfigNode> plugin_nodes;  ///< the `plugins:` entries, for errors naming them
};

/// Reads and checks a run config. @throws ConfigError naming file, line, key
/// and value, with the allowed values, for any mistake.
RunConfig LoadRunConfig(const ConfigNode& root);

/// LoadRunConfig(ConfigNode::LoadFile(path)).
RunConfig LoadRunConfigFile(const std::string& path);

/// The text to store as a run folder's config.yaml: `text` (the config's
/// bytes) as is, or, when it names plugins by relative paths, with a
/// `plugin_dir:` line appended so the copy finds the same plugins.
std::string RunFolderConfigText(const RunConfig& config, const std::string& text);

}  // namespace dream::config
