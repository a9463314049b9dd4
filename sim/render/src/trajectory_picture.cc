#include "dream/render/trajectory_picture.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "arena_painter.h"
#include "dream/render/run_geometry.h"
#include "picture_surface.h"
#include "violation_painter.h"

namespace dream::render {

void TrajectoryPicture::Render(const run_log::RunLog& log, const ArenaOverlays& overlays, const std::string& path,
                               RenderFormat format, int width_px) {
  Drawable(log);
  const bool violations = overlays.violations.total() > 0;
  const ArenaLayout layout(width_px, violations ? 2 : 1);
  PictureSurface surface(format, layout.width_px(), layout.height_px());
  const ArenaPainter painter(surface.cr(), layout);
  painter.Background();
  painter.ObstaclePaths(MovingObstaclePaths(log));
  const size_t last_index = log.poses().size() - 1;
  const std::vector<rectangle_obstacle_t>& obstacles = log.obstacles_at(last_index).obstacles;
  painter.Obstacles(obstacles);
  painter.Goals(overlays.goals_m);
  const robot_poses_t& first = log.poses().front();
  const robot_poses_t& last = log.poses().back();
  painter.SensorRanges(overlays, last, /*tint=*/true);
  painter.RadioLinks(overlays, log, last_index, 0);
  painter.Drawings(overlays, log, last.step);

  for (int32_t i = 0; i < log.num_robots(); ++i) {
    const auto k = static_cast<size_t>(i);
    painter.Track(i, RobotPath(log, i), 2.0);
    if (i < first.num_robots) {
      painter.Robot(i, first.x[k], first.y[k], first.theta[k], ArenaPainter::RobotLook::kHollow, false, 0.6);
    }
  }
  for (int32_t i = 0; i < last.num_robots; ++i) {
    const auto k = static_cast<size_t>(i);
    painter.Robot(i, last.x[k], last.y[k], last.theta[k], ArenaPainter::RobotLook::kFilled, true);
  }
  ViolationPainter(surface.cr(), layout).Mark(overlays.violations.listed);

  using Item = ArenaPainter::LegendItem;
  std::vector<Item> legend = {{Item::Marker::kRobot, "start", ArenaPainter::RobotLook::kHollow, 0.6},
                              {Item::Marker::kRobot, "end", ArenaPainter::RobotLook::kFilled, 1.0}};
  if (!overlays.goals_m.empty()) legend.push_back({Item::Marker::kGoal, "goal"});
  if (!obstacles.empty()) legend.push_back({Item::Marker::kObstacle, "obstacle"});
  if (violations) legend.push_back({Item::Marker::kViolation, "violation (k = its first step)"});
  painter.Legend(legend);
  painter.Caption(0, Caption(log, overlays));
  if (violations) painter.Caption(1, ViolationCaption(overlays.violations));
  surface.Commit(path);
}

std::string TrajectoryPicture::ViolationCaption(const world::LocatedViolations& violations) {
  const int64_t listed = static_cast<int64_t>(violations.listed.size());
  std::string text = std::to_string(violations.total()) + (violations.total() == 1 ? " violation" : " violations");
  if (listed > 0) {
    int64_t first = violations.listed.front().first_step;
    for (const world::LocatedViolation& v : violations.listed) first = std::min(first, v.first_step);
    text += ", the first at k=" + std::to_string(first);
  }
  if (violations.unlisted > 0) {
    text += "; " + std::to_string(listed) + " marked, " + std::to_string(violations.unlisted) + " more not";
  }
  return text + " (summary.json violations_located)";
}

std::string TrajectoryPicture::Caption(const run_log::RunLog& log, const ArenaOverlays& overlays) {
  char stats[160];
  std::snprintf(stats, sizeof(stats), "%d robots, steps %lld..%lld (%.1f s)", log.num_robots(),
                static_cast<long long>(log.first_step()), static_cast<long long>(log.last_step()), DurationS(log));
  return RunLabel(overlays) + stats;
}

}  // namespace dream::render
