#pragma once

#include <cairo.h>

#include <vector>

#include "dream/lcm/drawn_shape.h"
#include "dream/render/arena_layout.h"
#include "dream/run_log/recorded_drawing.h"

namespace dream::render {

/// Draws what controllers drew (DREAM_DRAW_<id>, run_log::RecordedDrawing)
/// in world coordinates: lines, circles, polygons, arrows and text, each in
/// its own colour and width (metres, at least a pixel). ArenaPainter::Drawings
/// clips it to the arena.
/// The same look as the view's (app/view/assets/arena.js, drawShapes).
class DrawingPainter {
 public:
  DrawingPainter(cairo_t* cr, const ArenaLayout& layout) : cr_(cr), layout_(layout) {}

  /// Every shape of `drawings`, in order (robot by robot, as drawn); the
  /// context's state is restored after.
  void Paint(const std::vector<const run_log::RecordedDrawing*>& drawings) const;
  void Shape(const lcm::DrawnShape& shape) const;

 private:
  void SetColor(uint32_t rgba) const;
  void Stroke(const lcm::DrawnShape& shape) const;
  void ArrowHead(double x0, double y0, double x1, double y1, double line_px) const;

  cairo_t* cr_;
  const ArenaLayout& layout_;
};

}  // namespace dream::render
