#include "dream/sim/trajectory_picture.h"

#include <cairo.h>
#include <unistd.h>

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

namespace dream::sim {
namespace {

// Matplotlib's tab10, so pictures look like the Robotarium's own plots.
constexpr std::array<std::array<double, 3>, 10> kColors = {{{0.12, 0.47, 0.71},
                                                            {1.00, 0.50, 0.05},
                                                            {0.17, 0.63, 0.17},
                                                            {0.84, 0.15, 0.16},
                                                            {0.58, 0.40, 0.74},
                                                            {0.55, 0.34, 0.29},
                                                            {0.89, 0.47, 0.76},
                                                            {0.50, 0.50, 0.50},
                                                            {0.74, 0.74, 0.13},
                                                            {0.09, 0.75, 0.81}}};

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
  const Arena arena;
  const double margin_px = 30.0;
  const double scale = (width_px - 2 * margin_px) / arena.width_m();
  const int height_px = static_cast<int>(std::lround(arena.height_m() * scale + 2 * margin_px + 24));
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width_px, height_px), cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  cairo_t* c = cr.get();
  auto px = [&](double x_m) { return margin_px + (x_m - arena.x_min_m) * scale; };
  auto py = [&](double y_m) { return margin_px + (arena.y_max_m - y_m) * scale; };

  cairo_set_source_rgb(c, 1, 1, 1);
  cairo_paint(c);
  // Half-metre grid, then the arena boundary.
  cairo_set_source_rgb(c, 0.9, 0.9, 0.9);
  cairo_set_line_width(c, 1.0);
  for (double x = -1.5; x <= 1.51; x += 0.5) {
    cairo_move_to(c, px(x), py(arena.y_min_m));
    cairo_line_to(c, px(x), py(arena.y_max_m));
  }
  for (double y = -1.0; y <= 1.01; y += 0.5) {
    cairo_move_to(c, px(arena.x_min_m), py(y));
    cairo_line_to(c, px(arena.x_max_m), py(y));
  }
  cairo_stroke(c);
  cairo_set_source_rgb(c, 0, 0, 0);
  cairo_set_line_width(c, 2.0);
  cairo_rectangle(c, px(arena.x_min_m), py(arena.y_max_m), arena.width_m() * scale, arena.height_m() * scale);
  cairo_stroke(c);

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
    const auto& rgb = kColors[static_cast<size_t>(i) % kColors.size()];
    cairo_set_source_rgb(c, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(c, 2.0);
    bool started = false;
    for (const robot_poses_t& poses : track.poses) {
      if (i >= poses.num_robots) continue;
      const auto k = static_cast<size_t>(i);
      if (!started) cairo_move_to(c, px(poses.x[k]), py(poses.y[k]));
      cairo_line_to(c, px(poses.x[k]), py(poses.y[k]));
      started = true;
    }
    cairo_stroke(c);
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
  cairo_set_source_rgb(c, 0.2, 0.2, 0.2);
  cairo_select_font_face(c, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(c, 14.0);
  cairo_move_to(c, margin_px, height_px - 10.0);
  cairo_show_text(c, caption);

  cairo_surface_flush(surface.get());
  const std::string temp = png_path + ".tmp." + std::to_string(::getpid());
  if (cairo_surface_write_to_png(surface.get(), temp.c_str()) != CAIRO_STATUS_SUCCESS ||
      std::rename(temp.c_str(), png_path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw std::runtime_error("cannot write the picture " + png_path + " (does the folder exist?)");
  }
}

}  // namespace dream::sim
