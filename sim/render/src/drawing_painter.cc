#include "drawing_painter.h"

#include <algorithm>
#include <cmath>

#include "dream/drawing_t.hpp"

namespace dream::render {

void DrawingPainter::SetColor(uint32_t rgba) const {
  cairo_set_source_rgba(cr_, ((rgba >> 24) & 0xff) / 255.0, ((rgba >> 16) & 0xff) / 255.0, ((rgba >> 8) & 0xff) / 255.0,
                        (rgba & 0xff) / 255.0);
}

void DrawingPainter::Stroke(const lcm::DrawnShape& shape) const {
  cairo_set_line_width(cr_, std::max(1.0, shape.width_m * layout_.scale()));
  if (shape.fill) {
    cairo_fill(cr_);
  } else {
    cairo_stroke(cr_);
  }
}

void DrawingPainter::ArrowHead(double x0, double y0, double x1, double y1, double line_px) const {
  const double length = std::hypot(x1 - x0, y1 - y0);
  if (length <= 0) return;
  const double head = std::min(std::max(8.0, 4.0 * line_px), 0.5 * length);
  const double ux = (x1 - x0) / length;
  const double uy = (y1 - y0) / length;
  cairo_move_to(cr_, x1, y1);
  cairo_line_to(cr_, x1 - head * ux - 0.5 * head * uy, y1 - head * uy + 0.5 * head * ux);
  cairo_line_to(cr_, x1 - head * ux + 0.5 * head * uy, y1 - head * uy - 0.5 * head * ux);
  cairo_close_path(cr_);
  cairo_fill(cr_);
}

void DrawingPainter::Shape(const lcm::DrawnShape& shape) const {
  if (shape.x_m.empty()) return;
  SetColor(shape.rgba);
  const double line_px = std::max(1.0, shape.width_m * layout_.scale());
  const double x0 = layout_.px(shape.x_m[0]);
  const double y0 = layout_.py(shape.y_m[0]);
  cairo_new_path(cr_);
  switch (shape.kind) {
    case drawing_t::LINE:
    case drawing_t::ARROW: {
      const double x1 = layout_.px(shape.x_m[1]);
      const double y1 = layout_.py(shape.y_m[1]);
      cairo_move_to(cr_, x0, y0);
      cairo_line_to(cr_, x1, y1);
      Stroke(lcm::DrawnShape{shape.kind, shape.rgba, shape.width_m, 0, false, {}, {}, {}});
      if (shape.kind == drawing_t::ARROW) ArrowHead(x0, y0, x1, y1, line_px);
      break;
    }
    case drawing_t::CIRCLE:
      cairo_arc(cr_, x0, y0, shape.size_m * layout_.scale(), 0, 2 * M_PI);
      Stroke(shape);
      break;
    case drawing_t::POLYGON:
      cairo_move_to(cr_, x0, y0);
      for (size_t i = 1; i < shape.x_m.size(); ++i)
        cairo_line_to(cr_, layout_.px(shape.x_m[i]), layout_.py(shape.y_m[i]));
      cairo_close_path(cr_);
      Stroke(shape);
      break;
    case drawing_t::TEXT:
      cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
      cairo_set_font_size(cr_, std::max(4.0, shape.size_m * layout_.scale()));
      cairo_move_to(cr_, x0, y0);
      cairo_show_text(cr_, shape.text.c_str());
      break;
    default:
      break;
  }
}

void DrawingPainter::Paint(const std::vector<const run_log::RecordedDrawing*>& drawings) const {
  if (drawings.empty()) return;
  cairo_save(cr_);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  for (const run_log::RecordedDrawing* drawing : drawings) {
    for (const lcm::DrawnShape& shape : drawing->shapes) Shape(shape);
  }
  cairo_restore(cr_);
}

}  // namespace dream::render
