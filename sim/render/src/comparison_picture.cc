#include "dream/sim/comparison_picture.h"

#include <cairo.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "arena_canvas.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/sim/robotarium_constants.h"

namespace dream::sim {
namespace {

struct Poses {
  std::vector<robot_poses_t> steps;
  obstacles_t last_obstacles{};
};

Poses ReadPoses(const std::string& log_path) {
  Poses poses;
  lcm::LogReader reader(log_path);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    const int size = static_cast<int>(record.data.size());
    if (record.channel == lcm::kPosesChannel) {
      robot_poses_t message;
      if (lcm::Decode(record.data.data(), size, &message)) poses.steps.push_back(std::move(message));
    } else if (record.channel == lcm::kObstaclesChannel) {
      obstacles_t message;
      if (lcm::Decode(record.data.data(), size, &message)) poses.last_obstacles = std::move(message);
    }
  }
  if (poses.steps.empty()) {
    throw std::runtime_error(log_path + ": the log holds no DREAM_POSES messages, so there is nothing to draw");
  }
  return poses;
}

void DrawTrack(render::ArenaCanvas& canvas, const std::vector<robot_poses_t>& steps, int robot) {
  const auto k = static_cast<size_t>(robot);
  std::vector<std::array<double, 2>> points;
  points.reserve(steps.size());
  for (const robot_poses_t& poses : steps) {
    if (robot < poses.num_robots) points.push_back({canvas.px(poses.x[k]), canvas.py(poses.y[k])});
  }
  canvas.StrokePolyline(points);
}

}  // namespace

void ComparisonPicture::Render(const std::string& first_log, const std::string& second_log,
                               const std::string& png_path, const std::vector<std::string>& caption_lines,
                               int width_px) {
  const Poses first = ReadPoses(first_log);
  const Poses second = ReadPoses(second_log);
  render::ArenaCanvas canvas(width_px, static_cast<int>(caption_lines.size()));
  cairo_t* c = canvas.cr();
  const double scale = canvas.scale();

  cairo_set_source_rgb(c, 0.25, 0.25, 0.25);
  for (const rectangle_obstacle_t& o : second.last_obstacles.obstacles) {
    cairo_rectangle(c, canvas.px(o.center_x - o.width / 2), canvas.py(o.center_y + o.height / 2), o.width * scale,
                    o.height * scale);
    cairo_fill(c);
  }
  const int robots = std::max(first.steps.back().num_robots, second.steps.back().num_robots);
  const double radius_px = RobotariumConstants::kRobotDiameterMeters / 2 * scale;
  const double dash[] = {7.0, 4.0};
  for (int i = 0; i < robots; ++i) {
    const auto& rgb = render::RobotColor(i);
    const auto k = static_cast<size_t>(i);
    cairo_set_source_rgba(c, rgb[0], rgb[1], rgb[2], 0.8);
    cairo_set_line_width(c, 1.5);
    cairo_set_dash(c, dash, 2, 0);
    DrawTrack(canvas, first.steps, i);
    cairo_set_dash(c, nullptr, 0, 0);
    cairo_set_source_rgb(c, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(c, 2.0);
    DrawTrack(canvas, second.steps, i);
    if (i < first.steps.back().num_robots) {
      cairo_arc(c, canvas.px(first.steps.back().x[k]), canvas.py(first.steps.back().y[k]), radius_px, 0, 2 * M_PI);
      cairo_stroke(c);
    }
    if (i < second.steps.back().num_robots) {
      const robot_poses_t& last = second.steps.back();
      cairo_arc(c, canvas.px(last.x[k]), canvas.py(last.y[k]), radius_px * 0.8, 0, 2 * M_PI);
      cairo_fill(c);
      cairo_set_source_rgb(c, 0, 0, 0);
      cairo_move_to(c, canvas.px(last.x[k]), canvas.py(last.y[k]));
      cairo_line_to(c, canvas.px(last.x[k] + 1.6 * radius_px / scale * std::cos(last.theta[k])),
                    canvas.py(last.y[k] + 1.6 * radius_px / scale * std::sin(last.theta[k])));
      cairo_stroke(c);
    }
  }
  for (size_t line = 0; line < caption_lines.size(); ++line) canvas.Caption(static_cast<int>(line), caption_lines[line]);
  canvas.WritePng(png_path);
}

}  // namespace dream::sim
