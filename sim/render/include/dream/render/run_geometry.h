#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "dream/run_log/run_log.h"

namespace dream::render {

// What pictures and plots compute from a run (run_log::RunLog, the one
// reader of a run's log): works on any log with DREAM_POSES, simulated or
// imported from the lab.

/// `log`, when it has poses to draw.
/// @throws std::runtime_error "no poses in <log>: nothing to render" when it has none.
const run_log::RunLog& Drawable(const run_log::RunLog& log);

/// Simulated seconds from the first to the last step (0.033 s a step).
double DurationS(const run_log::RunLog& log);

/// Robot `robot`'s centre {x, y} at poses()[from_index .. to_index] (to the
/// last pose by default), where the poses have that robot.
std::vector<std::array<double, 2>> RobotPath(const run_log::RunLog& log, int robot, size_t from_index = 0,
                                             size_t to_index = static_cast<size_t>(-1));

/// The centre path of each obstacle that moved during the run, by id.
std::vector<std::vector<std::array<double, 2>>> MovingObstaclePaths(const run_log::RunLog& log);

/// {step, distance between the two closest robot centres, metres} per step
/// with at least two robots.
std::vector<std::array<double, 2>> MinimumDistanceSeries(const run_log::RunLog& log);

}  // namespace dream::render
