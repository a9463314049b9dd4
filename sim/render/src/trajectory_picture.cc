#include "dream/render/trajectory_picture.h"

#include <cstdio>
#include <vector>

#include "arena_painter.h"
#include "dream/render/run_geometry.h"
#include "picture_surface.h"

namespace dream::render {

void TrajectoryPicture::Render(const run_log::RunLog& log, const ArenaOverlays& overlays, const std::string& path,
                               RenderFormat format, int width_px) {
  Drawable(log);
  const ArenaLayout layout(width_px, 1);
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

  using Item = ArenaPainter::LegendItem;
  std::vector<Item> legend = {{Item::Marker::kRobot, "start", ArenaPainter::RobotLook::kHollow, 0.6},
                              {Item::Marker::kRobot, "end", ArenaPainter::RobotLook::kFilled, 1.0}};
  if (!overlays.goals_m.empty()) legend.push_back({Item::Marker::kGoal, "goal"});
  if (!obstacles.empty()) legend.push_back({Item::Marker::kObstacle, "obstacle"});
  painter.Legend(legend);
  painter.Caption(0, Caption(log, overlays));
  surface.Commit(path);
}

std::string TrajectoryPicture::Caption(const run_log::RunLog& log, const ArenaOverlays& overlays) {
  char stats[160];
  std::snprintf(stats, sizeof(stats), "%d robots, steps %lld..%lld (%.1f s)", log.num_robots(),
                static_cast<long long>(log.first_step()), static_cast<long long>(log.last_step()), DurationS(log));
  return RunLabel(overlays) + stats;
}

}  // namespace dream::render
