#include "dream/sim/trajectory_picture.h"

#include <cairo.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/sim/arena.h"
#include "dream/sim/robotarium_constants.h"
#include "arena_canvas.h"

namespace dream::sim {
namespace {

struct Track {
  std::vector<robot_poses_t> poses;
  std::map<int32_t, std::vector<std::array<double, 2>>> obstacle_paths;
  obstacles_t last_obstacles{};
};

Track ReadTrack(const std::string& log_path) {
  Track track;
  lcm::LogReader reader(log_path);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    const int size = static_cast<int>(record.data.size());
    if (record.channel == lcm::kPosesChannel) {
      robot_poses_t poses;
      if (lcm::Decode(record.data.data(), size, &poses)) track.poses.push_back(std::move(poses));
    } else if (record.channel == lcm::kObstaclesChannel) {
      obstacles_t obstacles;
      if (!lcm::Decode(record.data.data(), size, &obstacles)) continue;
      for (const rectangle_obstacle_t& o : obstacles.obstacles) {
        track.obstacle_paths[o.id].push_back({o.center_x, o.center_y});
      }
      track.last_obstacles = std::move(obstacles);
    }
  }
  if (track.poses.empty()) {
    throw std::runtime_error(log_path + ": the log holds no DREAM_POSES messages, so there is nothing to draw");
  }
  return track;
}

}  // namespace

void TrajectoryPicture::Render(const std::string& log_path, const std::string& png_path, int width_px) {
  const Track track = ReadTrack(log_path);
  render::ArenaCanvas canvas(width_px, 1);
  cairo_t* c = canvas.cr();
  const double scale = canvas.scale();
  auto px = [&canvas](double x_m) { return canvas.px(x_m); };
  auto py = [&canvas](double y_m) { return canvas.py(y_m); };

  // Obstacles: dashed centre paths, then the rectangles where they ended.
  const double dash = 6.0;
  cairo_set_dash(c, &dash, 1, 0);
  cairo_set_source_rgb(c, 0.5, 0.5, 0.5);
  cairo_set_line_width(c, 1.0);
  for (const auto& [id, path] : track.obstacle_paths) {
    (void)id;
    for (size_t i = 0; i < path.size(); ++i) {
      if (i == 0) cairo_move_to(c, px(path[i][0]), py(path[i][1]));
      cairo_line_to(c, px(path[i][0]), py(path[i][1]));
    }
    cairo_stroke(c);
  }
  cairo_set_dash(c, nullptr, 0, 0);
  cairo_set_source_rgb(c, 0.25, 0.25, 0.25);
  for (const rectangle_obstacle_t& o : track.last_obstacles.obstacles) {
    cairo_rectangle(c, px(o.center_x - o.width / 2), py(o.center_y + o.height / 2), o.width * scale, o.height * scale);
    cairo_fill(c);
  }

  // Trajectories, start markers, final poses.
  const robot_poses_t& first = track.poses.front();
  const robot_poses_t& last = track.poses.back();
  const double radius_px = RobotariumConstants::kRobotDiameterMeters / 2 * scale;
  for (int32_t i = 0; i < last.num_robots; ++i) {
    const auto& rgb = render::RobotColor(i);
    cairo_set_source_rgb(c, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(c, 2.0);
    std::vector<std::array<double, 2>> points;
    points.reserve(track.poses.size());
    for (const robot_poses_t& poses : track.poses) {
      if (i >= poses.num_robots) continue;
      const auto k = static_cast<size_t>(i);
      points.push_back({px(poses.x[k]), py(poses.y[k])});
    }
    canvas.StrokePolyline(points);
    const auto k = static_cast<size_t>(i);
    if (i < first.num_robots) {
      cairo_arc(c, px(first.x[k]), py(first.y[k]), radius_px * 0.6, 0, 2 * M_PI);
      cairo_stroke(c);
    }
    cairo_arc(c, px(last.x[k]), py(last.y[k]), radius_px, 0, 2 * M_PI);
    cairo_fill(c);
    cairo_set_source_rgb(c, 0, 0, 0);
    cairo_move_to(c, px(last.x[k]), py(last.y[k]));
    cairo_line_to(c, px(last.x[k] + 1.6 * RobotariumConstants::kRobotDiameterMeters / 2 * std::cos(last.theta[k])),
                  py(last.y[k] + 1.6 * RobotariumConstants::kRobotDiameterMeters / 2 * std::sin(last.theta[k])));
    cairo_stroke(c);
  }

  char caption[160];
  std::snprintf(caption, sizeof(caption), "%d robots, steps %lld..%lld (%.1f s)", last.num_robots,
                static_cast<long long>(first.step), static_cast<long long>(last.step),
                static_cast<double>(last.step - first.step) * RobotariumConstants::kTimeStepSeconds);
  canvas.Caption(0, caption);
  canvas.WritePng(png_path);
}

}  // namespace dream::sim
