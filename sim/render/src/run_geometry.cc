#include "dream/render/run_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "dream/robotarium/robotarium_constants.h"

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

}  // namespace dream::render
