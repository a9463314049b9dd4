#include "dream/render/trajectory_picture.h"

#include <cstdio>
#include <vector>

#include "arena_painter.h"
#include "picture_surface.h"

namespace dream::sim {

void TrajectoryPicture::Render(const std::string& log_path, const std::string& png_path, int width_px) {
  Render(RunTrack::Read(log_path), ArenaOverlays{}, png_path, RenderFormat::kPng, width_px);
}

void TrajectoryPicture::Render(const RunTrack& track, const ArenaOverlays& overlays, const std::string& path,
                               RenderFormat format, int width_px) {
  const ArenaLayout layout(width_px, 1);
  PictureSurface surface(format, layout.width_px(), layout.height_px());
  const ArenaPainter painter(surface.cr(), layout);
  painter.Background();
  painter.ObstaclePaths(track.MovingObstaclePaths());
  const size_t last_index = track.poses().size() - 1;
  painter.Obstacles(track.obstacles_at(last_index));
  painter.Goals(overlays.goals_m);
  const robot_poses_t& first = track.poses().front();
  const robot_poses_t& last = track.poses().back();
  painter.SensorRanges(overlays, last, /*tint=*/true);
  painter.RadioLinks(overlays, track, last_index, 0);

  for (int32_t i = 0; i < track.num_robots(); ++i) {
    const auto k = static_cast<size_t>(i);
    std::vector<std::array<double, 2>> points;
    points.reserve(track.poses().size());
    for (const robot_poses_t& poses : track.poses()) {
      if (i < poses.num_robots) points.push_back({poses.x[k], poses.y[k]});
    }
    painter.Track(i, points, 2.0);
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
  if (!track.obstacles_at(last_index).empty()) legend.push_back({Item::Marker::kObstacle, "obstacle"});
  painter.Legend(legend);
  painter.Caption(0, Caption(track, overlays));
  surface.Commit(path);
}

std::string TrajectoryPicture::Caption(const RunTrack& track, const ArenaOverlays& overlays) {
  char stats[160];
  std::snprintf(stats, sizeof(stats), "%d robots, steps %lld..%lld (%.1f s)", track.num_robots(),
                static_cast<long long>(track.first_step()), static_cast<long long>(track.last_step()),
                track.duration_s());
  return RunLabel(overlays) + stats;
}

}  // namespace dream::sim
