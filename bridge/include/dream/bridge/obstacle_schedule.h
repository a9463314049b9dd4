#pragma once

#include <cstdint>
#include <vector>

#include "dream/bridge/npy_file.h"
#include "dream/world/rectangle_obstacle_spec.h"

namespace dream::bridge {

/// Every virtual obstacle at every step 0..steps, moved exactly as the
/// simulator's world moves them (sim::RectangleObstacle, one Advance per
/// step) and as DREAM_OBSTACLES reports them: a (steps + 1) x M x
/// ObstacleColumns array (id, centre, size, velocity of the current leg) for
/// a submission whose controllers sense the obstacles on the lab.
/// @throws std::invalid_argument for an invalid spec (as the world does).
NpyArray ObstacleSchedule(const std::vector<sim::RectangleObstacleSpec>& specs, double time_step_s, int64_t steps);

}  // namespace dream::bridge
