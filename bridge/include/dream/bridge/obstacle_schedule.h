#pragma once

#include <cstdint>
#include <vector>

#include "dream/formats/npy_file.h"
#include "dream/world/rectangle_obstacle_spec.h"

namespace dream::bridge {

/// The largest dream_obstacles.npy an export writes: 256 MiB, about 170
/// obstacles over the lab's 15 minutes (a config may have 10,000 obstacles,
/// whose schedule would be 15 GB).
inline constexpr int64_t kMaxObstacleScheduleBytes = int64_t{256} << 20;

/// Bytes of the schedule of `obstacles` over steps 0..steps (its numbers).
int64_t ObstacleScheduleBytes(int64_t obstacles, int64_t steps);

/// Every virtual obstacle at every step 0..steps, moved exactly as the
/// simulator's world moves them (world::RectangleObstacle, one Advance per
/// step) and as DREAM_OBSTACLES reports them: a (steps + 1) x M x
/// ObstacleColumns array (id, centre, size, velocity of the current leg) for
/// a submission whose controllers sense the obstacles on the lab.
/// @throws std::invalid_argument for an invalid spec (as the world does), or a
/// schedule over kMaxObstacleScheduleBytes.
formats::NpyArray ObstacleSchedule(const std::vector<world::RectangleObstacleSpec>& specs, double time_step_s,
                                   int64_t steps);

}  // namespace dream::bridge
