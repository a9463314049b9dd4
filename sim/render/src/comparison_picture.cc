#include "dream/render/comparison_picture.h"

#include <algorithm>
#include <vector>

#include "arena_painter.h"
#include "dream/render/run_geometry.h"
#include "picture_surface.h"

namespace dream::render {

void ComparisonPicture::Render(const run_log::RunLog& first, const run_log::RunLog& second, const std::string& png_path,
                               const std::vector<std::string>& caption_lines, int width_px) {
  Drawable(first);
  Drawable(second);
  const ArenaLayout layout(width_px, static_cast<int>(caption_lines.size()));
  PictureSurface surface(RenderFormat::kPng, layout.width_px(), layout.height_px());
  const ArenaPainter painter(surface.cr(), layout);
  painter.Background();
  const std::vector<rectangle_obstacle_t>& obstacles = second.obstacles_at(second.poses().size() - 1).obstacles;
  painter.Obstacles(obstacles);
  const robot_poses_t& start = second.poses().front();
  const robot_poses_t& first_end = first.poses().back();
  const robot_poses_t& second_end = second.poses().back();
  for (int i = 0; i < std::max(first.num_robots(), second.num_robots()); ++i) {
    const auto k = static_cast<size_t>(i);
    painter.Track(i, RobotPath(first, i), 1.5, 0.8, /*dashed=*/true);
    painter.Track(i, RobotPath(second, i), 2.0);
    if (i < start.num_robots) {  // where the runs began, as TrajectoryPicture marks it
      painter.Robot(i, start.x[k], start.y[k], start.theta[k], ArenaPainter::RobotLook::kHollow, false, 0.6);
    }
    if (i < first_end.num_robots) {
      painter.Robot(i, first_end.x[k], first_end.y[k], first_end.theta[k], ArenaPainter::RobotLook::kHollow);
    }
    if (i < second_end.num_robots) {
      // With its id: captions name robots ("robot 7 strays 0.12 m").
      painter.Robot(i, second_end.x[k], second_end.y[k], second_end.theta[k], ArenaPainter::RobotLook::kFilled, true,
                    0.8);
    }
  }
  using Item = ArenaPainter::LegendItem;
  std::vector<Item> legend = {{Item::Marker::kRobot, "start", ArenaPainter::RobotLook::kHollow, 0.6},
                              {Item::Marker::kRobot, "first run's end", ArenaPainter::RobotLook::kHollow, 1.0},
                              {Item::Marker::kRobot, "second run's end", ArenaPainter::RobotLook::kFilled, 0.8}};
  if (!obstacles.empty()) legend.push_back({Item::Marker::kObstacle, "obstacle"});
  painter.Legend(legend);
  for (size_t line = 0; line < caption_lines.size(); ++line)
    painter.Caption(static_cast<int>(line), caption_lines[line]);
  surface.Commit(png_path);
}

}  // namespace dream::render
