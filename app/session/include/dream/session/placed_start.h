#pragma once

#include "dream/node/run_recorder.h"
#include "dream/run_config/run_config.h"

namespace dream::session {

/// `world.start: placed`: the Robotarium's start-up drive (world::StartupDrive,
/// from the run's own placement, world::StartupDriveTrials::PlacementSeed(seed, 0))
/// before step 0. Its steps go to the run's log on DREAM_STARTUP_POSES, apart
/// from the experiment's (which still start at step 0, with no Robotarium
/// error counted for the drive), and the experiment starts where it ended.
class PlacedStart {
 public:
  /// `config` with its initial poses where the drive left the robots.
  /// @throws config::ConfigError naming robots and distances when the drive
  /// does not settle within the step limit (the CLI refuses such a run
  /// before, through run_config::StartupDriveCheck).
  static run_config::RunConfig Drive(const run_config::RunConfig& config, node::RunRecorder& recorder);
};

}  // namespace dream::session
