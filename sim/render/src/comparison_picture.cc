#include "dream/render/comparison_picture.h"

#include <algorithm>
#include <vector>

#include "arena_painter.h"
#include "dream/render/run_track.h"
#include "picture_surface.h"

namespace dream::sim {
namespace {

std::vector<std::array<double, 2>> PathOf(const RunTrack& track, int robot) {
  const auto k = static_cast<size_t>(robot);
  std::vector<std::array<double, 2>> points;
  points.reserve(track.poses().size());
  for (const robot_poses_t& poses : track.poses()) {
    if (robot < poses.num_robots) points.push_back({poses.x[k], poses.y[k]});
  }
  return points;
}

}  // namespace

void ComparisonPicture::Render(const std::string& first_log, const std::string& second_log,
                               const std::string& png_path, const std::vector<std::string>& caption_lines,
                               int width_px) {
  const RunTrack first = RunTrack::Read(first_log);
  const RunTrack second = RunTrack::Read(second_log);
  const ArenaLayout layout(width_px, static_cast<int>(caption_lines.size()));
  PictureSurface surface(RenderFormat::kPng, layout.width_px(), layout.height_px());
  const ArenaPainter painter(surface.cr(), layout);
  painter.Background();
  painter.Obstacles(second.obstacles_at(second.poses().size() - 1));
  const robot_poses_t& first_end = first.poses().back();
  const robot_poses_t& second_end = second.poses().back();
  for (int i = 0; i < std::max(first.num_robots(), second.num_robots()); ++i) {
    const auto k = static_cast<size_t>(i);
    painter.Track(i, PathOf(first, i), 1.5, 0.8, /*dashed=*/true);
    painter.Track(i, PathOf(second, i), 2.0);
    if (i < first_end.num_robots) {
      painter.Robot(i, first_end.x[k], first_end.y[k], first_end.theta[k], ArenaPainter::RobotLook::kHollow);
    }
    if (i < second_end.num_robots) {
      painter.Robot(i, second_end.x[k], second_end.y[k], second_end.theta[k], ArenaPainter::RobotLook::kFilled,
                    false, 0.8);
    }
  }
  using Item = ArenaPainter::LegendItem;
  std::vector<Item> legend = {{Item::Marker::kRobot, "first run's end", ArenaPainter::RobotLook::kHollow, 1.0},
                              {Item::Marker::kRobot, "second run's end", ArenaPainter::RobotLook::kFilled, 0.8}};
  if (!second.obstacles_at(second.poses().size() - 1).empty()) legend.push_back({Item::Marker::kObstacle, "obstacle"});
  painter.Legend(legend);
  for (size_t line = 0; line < caption_lines.size(); ++line) painter.Caption(static_cast<int>(line), caption_lines[line]);
  surface.Commit(png_path);
}

}  // namespace dream::sim
