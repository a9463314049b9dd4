#pragma once

#include <cairo.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "dream/sim/arena.h"

namespace dream::sim::render {

/// Matplotlib's tab10, so pictures look like the Robotarium's own plots.
const std::array<double, 3>& RobotColor(int robot_id);

/// A cairo image of the arena to scale: white, a half-metre grid, the
/// boundary, and room for caption lines below. px()/py() map metres to pixels.
class ArenaCanvas {
 public:
  ArenaCanvas(int width_px, int caption_lines);

  cairo_t* cr() const { return cr_.get(); }
  double px(double x_m) const { return margin_px_ + (x_m - arena_.x_min_m) * scale_; }
  double py(double y_m) const { return margin_px_ + (arena_.y_max_m - y_m) * scale_; }
  double scale() const { return scale_; }
  int height_px() const { return height_px_; }

  /// Strokes the polyline through `points_px` with the current source and
  /// line width, cheaply: points closer than a pixel to the last kept one are
  /// dropped, and a pixel-rounded segment already drawn is not drawn again
  /// (a robot that drives the same lap 100 times costs one lap). Keeps the
  /// look of the full polyline at this resolution.
  void StrokePolyline(const std::vector<std::array<double, 2>>& points_px);

  /// Writes `text` as caption line `line` (0 = first) under the arena.
  void Caption(int line, const std::string& text);
  /// Writes the PNG atomically. @throws std::runtime_error naming the path.
  void WritePng(const std::string& png_path);

 private:
  Arena arena_{};
  double margin_px_ = 30.0;
  double scale_ = 1.0;
  int height_px_ = 0;
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_;
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_;
};

}  // namespace dream::sim::render
