#pragma once

namespace dream::run_config {

/// `world.start`: where step 0 is.
enum class WorldStart {
  /// On the start poses, as the official simulator with skip_initialization
  /// (today's behaviour, the default).
  kExact,
  /// Where the Robotarium's start-up drive (world::StartupDrive) from random
  /// charger slots ended, as on the lab: near, not on, the start poses.
  kPlaced,
};

}  // namespace dream::run_config
