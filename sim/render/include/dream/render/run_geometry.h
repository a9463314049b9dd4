#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "dream/files/stop_token.h"
#include "dream/run_log/run_log.h"
#include "dream/world/located_violation.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/violation_tracker.h"
#include "dream/world/world_params.h"

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

/// `obstacles` as the world's checks take them (world::StepViolationLocator
/// leaves out those with values that are not finite), into `states`.
void ObstacleStatesOf(const obstacles_t& obstacles, std::vector<world::ObstacleState>* states);

/// Where and when the run broke the Robotarium's rules, by the world's own
/// checks (world::ViolationChecker) on the log's poses and obstacles of the
/// steps the world validated (all but the last, the final poses): robots
/// outside the arena, robots too close, robots on an obstacle, each a
/// world::LocatedViolation (consecutive steps of one violation are one
/// entry), at most `max_listed` of them, the rest counted. Works on any log
/// (simulated or imported from the lab); steps whose poses do not decode
/// whole (a robot count that changes, a value not finite) are skipped.
/// @throws files::Stopped when `stop` is requested (polled every 1000 steps).
world::LocatedViolations LocateViolations(const run_log::RunLog& log, const world::WorldParams& world = {},
                                          size_t max_listed = world::ViolationTracker::kDefaultMaxListed,
                                          const files::StopToken& stop = {});

}  // namespace dream::render
