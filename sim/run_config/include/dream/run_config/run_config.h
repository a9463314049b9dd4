#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dream/config/config_node.h"
#include "dream/run_config/barrier_config.h"
#include "dream/run_config/world_start.h"
#include "dream/config/controller_config.h"
#include "dream/world/pose2.h"
#include "dream/world/realism_params.h"
#include "dream/world/rectangle_obstacle_spec.h"
#include "dream/config/sim_node_options.h"
#include "dream/world/world_params.h"

namespace dream::run_config {

/// A whole run as described by one YAML file (see config/README.md for every
/// key). Initial poses are resolved here: from the file, or generated
/// collision-free from the seed, so every process of a run sees the same.
/// Either way no robot starts touching another or a virtual obstacle (where
/// the obstacle is at step 0).
///
/// The agents' part (name, seed, robots, controller, plugins) is the base
/// ControllerConfig: what an agent process reads, without the world.
struct RunConfig : config::ControllerConfig {
  /// The most `obstacles:` a run may have: what one DREAM_OBSTACLES message
  /// may carry (lcm::MessageLimits::kObstacles; decoder_bounds_test keeps
  /// them equal), so agents never refuse the world's own obstacles.
  static constexpr size_t kMaxObstacles = 10000;

  config::SimNodeOptions sim;  ///< pacing, timeouts, step limit
  /// `world.start`: step 0 on the start poses, or where the Robotarium's start-up drive left the robots.
  WorldStart start = WorldStart::kExact;
  world::WorldParams world;  ///< Robotarium V2 constants (not configurable)
  /// `world.realism:` (a preset name, or a map of models); Ideal(), the
  /// default, is the official simulator (no world::RealisticWorld).
  world::RealismParams realism;
  /// `world.realism: {file: PATH}` (a realism file, e.g. from dream calibrate):
  /// the path as written (relative to the config's folder, never leaving it,
  /// or absolute) and resolved; both empty without one.
  std::string realism_file_as_written;
  std::string realism_file;
  std::vector<world::Pose2> initial_poses;
  /// `initial_poses: {generate: {lab_safe: true}}`: their spacing (0: not lab-safe
  /// poses); StartupDriveCheck refuses them when the start-up drive does not settle.
  double lab_safe_spacing_m = 0.0;
  std::vector<world::RectangleObstacleSpec> obstacles;
  /// `barriers:`: the Robotarium's barrier certificate, if any, and where it is applied.
  BarrierConfig barriers;
  /// `script:`: the Robotarium script this run runs (dream run SCRIPT.py and
  /// dream sweep SCRIPT.py write it), as written; "" for a run of controllers.
  std::string script;
};

/// Reads and checks a run config. @throws ConfigError naming file, line, key
/// and value, with the allowed values, for any mistake.
RunConfig LoadRunConfig(const config::ConfigNode& root);

/// A realism file (what `dream calibrate` writes; `world.realism: {file:}`):
/// its keys over its own preset, or over ideal. @throws ConfigError naming
/// the file, line and key.
world::RealismParams LoadRealismFile(const std::string& path);

/// LoadRunConfig(ConfigNode::LoadFile(path)).
RunConfig LoadRunConfigFile(const std::string& path);

/// Where a run folder keeps its copy of the config's realism file (empty:
/// none): a relative path as written (beside the folder's config.yaml, as
/// beside the config), an absolute one (a file elsewhere, or given with
/// --set) as realism/<its name>.
std::string RealismFileInRunFolder(const RunConfig& config);

/// The text to store as a run folder's config.yaml: `text` (the config's
/// bytes) as is, or, when it names plugins by relative paths, with a
/// `plugin_dir:` line appended so the copy finds the same plugins; and with
/// an absolute realism file replaced by the folder's copy
/// (RealismFileInRunFolder), so the folder reruns on its own.
std::string RunFolderConfigText(const RunConfig& config, const std::string& text);

}  // namespace dream::run_config
