#include "dream/run_config/world_of_config.h"

#include "dream/world/barrier_world.h"
#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::run_config {

namespace {

std::unique_ptr<world::World> SteppingWorld(const RunConfig& config) {
  if (config.realism.IsIdeal()) {
    return std::make_unique<world::UnicycleWorld>(config.world, config.initial_poses, config.obstacles);
  }
  return std::make_unique<world::RealisticWorld>(config.world, config.realism, config.seed, config.initial_poses,
                                                 config.obstacles);
}

}  // namespace

std::unique_ptr<world::World> WorldOfConfig(const RunConfig& config) {
  std::unique_ptr<world::World> world = SteppingWorld(config);
  if (!config.barriers.InWorld()) return world;
  return std::make_unique<world::BarrierWorld>(std::move(world), config.barriers.unicycle);
}

}  // namespace dream::run_config
