#pragma once

#include <vector>

#include "dream/agents/framework/world_snapshot.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"

namespace dream::agent_host {

// The one conversion from the world's messages to the WorldSnapshot agents
// act on: the live AgentHost calls it on the bus, MetricsFromLog on a run's
// log, so metrics judge exactly the world the robots were given.

/// Puts a DREAM_POSES message into `world`: its step, and every robot's pose
/// (x m, y m, theta rad) and velocity (v m/s, w rad/s); the obstacles stay.
void TakePoses(const robot_poses_t& poses, agents::WorldSnapshot* world);

/// Puts a DREAM_OBSTACLES message into `world` as its obstacles, leaving out
/// any with a non-finite centre, size or velocity; their ids are added to
/// `non_finite` when given.
void TakeObstacles(const obstacles_t& obstacles, agents::WorldSnapshot* world, std::vector<int>* non_finite = nullptr);

}  // namespace dream::agent_host
