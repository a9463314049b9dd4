#include "dream/config/world_of_config.h"

#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::config {

std::unique_ptr<sim::World> WorldOfConfig(const RunConfig& config) {
  if (config.realism.IsIdeal()) {
    return std::make_unique<sim::UnicycleWorld>(config.world, config.initial_poses, config.obstacles);
  }
  return std::make_unique<sim::RealisticWorld>(config.world, config.realism, config.seed, config.initial_poses,
                                               config.obstacles);
}

}  // namespace dream::config
