#include "dream/render/run_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/violation_checker.h"

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

namespace {

/// The poses of `poses` as the checker takes them; false when they are not
/// `n` finite poses.
bool PosesOf(const robot_poses_t& poses, int n, std::vector<world::Pose2>* at) {
  const auto size = static_cast<size_t>(n);
  if (poses.num_robots != n || poses.x.size() != size || poses.y.size() != size || poses.theta.size() != size) {
    return false;
  }
  for (size_t i = 0; i < size; ++i) {
    if (!std::isfinite(poses.x[i]) || !std::isfinite(poses.y[i]) || !std::isfinite(poses.theta[i])) return false;
    (*at)[i] = {poses.x[i], poses.y[i], poses.theta[i]};
  }
  return true;
}

void ObstaclesOf(const obstacles_t& obstacles, std::vector<world::ObstacleState>* boxes) {
  boxes->clear();
  for (const rectangle_obstacle_t& o : obstacles.obstacles) {
    if (!std::isfinite(o.center_x) || !std::isfinite(o.center_y) || !std::isfinite(o.width) || !std::isfinite(o.height)) {
      continue;
    }
    boxes->push_back({o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
  }
}

}  // namespace

world::LocatedViolations LocateViolations(const run_log::RunLog& log, const world::WorldParams& world,
                                          size_t max_listed) {
  world::ViolationTracker tracker(max_listed);
  const int n = log.num_robots();
  if (n < 1 || log.poses().size() < 2) return tracker.located();
  world::ViolationChecker checker(world, n);
  std::vector<world::Pose2> at(static_cast<size_t>(n));
  std::vector<world::ObstacleState> boxes;
  // The last poses are where the run ended: the world never validated them.
  for (size_t i = 0; i + 1 < log.poses().size(); ++i) {
    if (!PosesOf(log.poses()[i], n, &at)) continue;
    ObstaclesOf(log.obstacles_at(i), &boxes);
    checker.Check(log.poses()[i].step, at, nullptr, boxes);
    tracker.Add(checker.last_step_events(), at);
  }
  return tracker.located();
}

}  // namespace dream::render
