#include "dream/render/run_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/step_violation_locator.h"

namespace dream::render {

const run_log::RunLog& Drawable(const run_log::RunLog& log) {
  if (log.poses().empty()) throw std::runtime_error("no poses in " + log.path() + ": nothing to render");
  return log;
}

double DurationS(const run_log::RunLog& log) {
  return static_cast<double>(log.last_step() - log.first_step()) * robotarium::RobotariumConstants::kTimeStepSeconds;
}

std::vector<std::array<double, 2>> RobotPath(const run_log::RunLog& log, int robot, size_t from_index,
                                             size_t to_index) {
  const std::vector<robot_poses_t>& poses = log.poses();
  if (poses.empty()) return {};
  const size_t end = std::min(to_index, poses.size() - 1) + 1;
  const auto k = static_cast<size_t>(robot);
  std::vector<std::array<double, 2>> points;
  points.reserve(end > from_index ? end - from_index : 0);
  for (size_t p = from_index; p < end; ++p) {
    if (robot < poses[p].num_robots) points.push_back({poses[p].x[k], poses[p].y[k]});
  }
  return points;
}

std::vector<std::vector<std::array<double, 2>>> MovingObstaclePaths(const run_log::RunLog& log) {
  std::map<int32_t, std::vector<std::array<double, 2>>> paths;
  for (const obstacles_t& obstacles : log.obstacles()) {
    for (const rectangle_obstacle_t& o : obstacles.obstacles) {
      std::vector<std::array<double, 2>>& path = paths[o.id];
      if (path.empty() || path.back()[0] != o.center_x || path.back()[1] != o.center_y) {
        path.push_back({o.center_x, o.center_y});
      }
    }
  }
  std::vector<std::vector<std::array<double, 2>>> moving;
  for (auto& [id, path] : paths) {
    (void)id;
    if (path.size() > 1) moving.push_back(std::move(path));
  }
  return moving;
}

std::vector<std::array<double, 2>> MinimumDistanceSeries(const run_log::RunLog& log) {
  std::vector<std::array<double, 2>> series;
  series.reserve(log.poses().size());
  for (const robot_poses_t& poses : log.poses()) {
    double closest_sq = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < poses.x.size(); ++i) {
      for (size_t j = i + 1; j < poses.x.size(); ++j) {
        const double dx = poses.x[i] - poses.x[j];
        const double dy = poses.y[i] - poses.y[j];
        closest_sq = std::min(closest_sq, dx * dx + dy * dy);
      }
    }
    if (std::isfinite(closest_sq)) series.push_back({static_cast<double>(poses.step), std::sqrt(closest_sq)});
  }
  return series;
}

void ObstacleStatesOf(const obstacles_t& obstacles, std::vector<world::ObstacleState>* states) {
  states->clear();
  for (const rectangle_obstacle_t& o : obstacles.obstacles) {
    states->push_back({o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
  }
}

world::LocatedViolations LocateViolations(const run_log::RunLog& log, const world::WorldParams& world,
                                          size_t max_listed, const files::StopToken& stop) {
  constexpr size_t kStepsPerPoll = 1000;
  world::ViolationTracker tracker(max_listed);
  const int n = log.num_robots();
  if (n < 1 || log.poses().size() < 2) return tracker.located();
  world::StepViolationLocator locator(world);
  std::vector<world::ObstacleState> boxes;
  std::vector<world::LocatedViolation> placed;
  for (size_t i = 0; i < log.judged_poses(); ++i) {
    if (i % kStepsPerPoll == 0) stop.ThrowIfRequested();
    const robot_poses_t& poses = log.poses()[i];
    if (poses.num_robots != n) continue;  // the log's robots, or none: ids must mean the same robots
    ObstacleStatesOf(log.obstacles_at(i), &boxes);
    placed.clear();
    if (locator.Locate(poses.step, n, poses.x, poses.y, poses.theta, boxes, &placed)) {
      tracker.AddPlaced(poses.step, placed);
    }
  }
  return tracker.located();
}

}  // namespace dream::render
