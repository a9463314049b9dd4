#pragma once

#include <nlohmann/json.hpp>

#include "dream/agent_host/controller_factory.h"
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
render::ArenaOverlays ArenaOverlaysFromConfig(const run_config::RunConfig& config, const agent_host::ControllerFactory& factory);

/// The goals a run's metrics declare (summary.json metrics.goal_points: a
/// Python controller's goal_points(), per robot [[x, y], ...]) when the kind
/// drew none; malformed entries are skipped.
void AddDeclaredGoals(const nlohmann::json& metrics, render::ArenaOverlays* overlays);

}  // namespace dream::session
