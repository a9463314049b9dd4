#pragma once

#include <vector>

#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/world/obstacle_state.h"
#include "dream/world/world.h"

namespace dream::node {

/// The world at its current step as the messages agents are sent
/// (DREAM_OBSTACLES, DREAM_POSES) and the world's part of DREAM_STATUS: step,
/// counts and values. The caller sets utime and run_id. SimNode publishes these; the config fuzz target feeds
/// them to agents through the same TakeObstacles/TakePoses as the bus.
class WorldMessages {
 public:
  /// Every obstacle of the step; `scratch` keeps its buffer across steps.
  static void Fill(const world::World& world, std::vector<world::ObstacleState>* scratch, obstacles_t* obstacles);
  /// Every robot's pose, and the velocity it drove with during the last
  /// step (zero before the first): what a tracker on the lab would measure.
  static void Fill(const world::World& world, robot_poses_t* poses);
  /// The step, robot count and violation counts; the caller sets the rest
  /// (state, detail, and what the node counts: rejected commands, conflicts,
  /// lost robots, which stay as they were).
  static void Fill(const world::World& world, run_status_t* status);
};

}  // namespace dream::node
