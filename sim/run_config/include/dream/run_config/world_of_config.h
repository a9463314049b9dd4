#pragma once

#include <memory>

#include "dream/run_config/run_config.h"
#include "dream/world/world.h"

namespace dream::run_config {

/// The world a run config asks for: the official simulator's UnicycleWorld
/// when `world.realism` is ideal (nothing in between), else a RealisticWorld
/// seeded by the config's seed (in a world::BarrierWorld when `barriers:` has
/// the world apply a certificate). What `dream run`'s session steps, and what
/// the config fuzz target steps without a bus.
/// @throws std::invalid_argument for params the world refuses (LoadRunConfig
/// has checked them all).
std::unique_ptr<world::World> WorldOfConfig(const RunConfig& config);

}  // namespace dream::run_config
