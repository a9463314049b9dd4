#pragma once

#include <memory>

#include "dream/config/run_config.h"
#include "dream/world/world.h"

namespace dream::config {

/// The world a run config asks for: the official simulator's UnicycleWorld
/// when `world.realism` is ideal (nothing in between), else a RealisticWorld
/// seeded by the config's seed. What `dream run`'s session steps, and what
/// the config fuzz target steps without a bus.
/// @throws std::invalid_argument for params the world refuses (LoadRunConfig
/// has checked them all).
std::unique_ptr<sim::World> WorldOfConfig(const RunConfig& config);

}  // namespace dream::config
