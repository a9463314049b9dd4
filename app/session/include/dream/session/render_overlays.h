#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/lcm/message_limits.h"
#include "dream/run_config/run_config.h"
#include "dream/render/arena_overlays.h"

namespace dream::session {

/// What a run's config adds to its pictures (render::ArenaOverlays), read with
/// the agents' own code so a picture shows what the robots had:
///  - goals: what the kind says its robots should reach (ExperimentBuilder::GoalsToDraw);
///  - sensor reaches: the movement and obstacle sensors of the robots' parts
///    (the experiment's defaults unless the config overrides them);
///  - who hears whom: each robot's radio (range, graph or role) deciding as
///    it does in a run.
/// The draw_* flags are left off. @throws config::ConfigError naming the key.
render::ArenaOverlays ArenaOverlaysFromConfig(const run_config::RunConfig& config);

/// The same with the run's factory, when the caller has one already.
render::ArenaOverlays ArenaOverlaysFromConfig(const run_config::RunConfig& config,
                                              const agent_host::ControllerFactory& factory);

/// The goals a run's metrics declare (summary.json metrics.goal_points: a
/// Python controller's goal_points(), per robot [[x, y], ...]) when the kind
/// drew none; malformed entries are skipped, and what lies beyond
/// kMaxGoalRobots robots or kMaxGoalPointsPerRobot points of one robot (more
/// than any run has: a summary.json is a file anyone may have edited).
void AddDeclaredGoals(const nlohmann::json& metrics, render::ArenaOverlays* overlays);

/// Robots a message on the bus may carry.
inline constexpr size_t kMaxGoalRobots = lcm::MessageLimits::kRobots;
/// As python/dream/run_metrics.py bounds a goal_points() list.
inline constexpr size_t kMaxGoalPointsPerRobot = 1000;

/// The goals a finished run's summary.json (at `summary_path`) declares, by
/// AddDeclaredGoals; false when the file is missing, too large, malformed or
/// declares none (goals are a drawing's nicety: nothing to fail for).
bool AddDeclaredGoalsOfRun(const std::string& summary_path, render::ArenaOverlays* overlays);

/// The goals the run's kind knows before the run, when its builder drew none
/// (ControllerKind::goals_before_run: a Python controller's class's
/// goal_points(config, num_robots), through a short-lived python3 with the
/// Python runtime in `runtime_dir`), bounded as AddDeclaredGoals bounds them.
/// Nothing for a kind without them or without `runtime_dir`.
/// @throws std::runtime_error naming the module and what failed (its
///         exception with file and line, a bad return value, a timeout).
void AddKindGoals(const run_config::RunConfig& config, const std::string& runtime_dir, render::ArenaOverlays* overlays);

}  // namespace dream::session
