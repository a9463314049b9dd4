#include "dream/render/xy_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "arena_painter.h"
#include "picture_surface.h"
#include "plot_ticks.h"

namespace dream::render {
namespace {

struct Bounds {
  double x_lo = std::numeric_limits<double>::infinity();
  double x_hi = -std::numeric_limits<double>::infinity();
  double y_lo = std::numeric_limits<double>::infinity();
  double y_hi = -std::numeric_limits<double>::infinity();
};

Bounds BoundsOf(const XyPanel& panel) {
  Bounds b;
  for (const XySeries& s : panel.series) {
    for (const auto& p : s.points) {
      if (!std::isfinite(p[0]) || !std::isfinite(p[1])) continue;
      b.x_lo = std::min(b.x_lo, p[0]);
      b.x_hi = std::max(b.x_hi, p[0]);
      b.y_lo = std::min(b.y_lo, p[1]);
      b.y_hi = std::max(b.y_hi, p[1]);
    }
  }
  auto pad = [](double* lo, double* hi) {
    if (*hi - *lo < 1e-12) {
      const double extra = std::max(std::abs(*hi) * 0.1, 1e-3);
      *lo -= extra;
      *hi += extra;
    }
    const double margin = (*hi - *lo) * 0.05;
    *lo -= margin;
    *hi += margin;
  };
  pad(&b.x_lo, &b.x_hi);
  pad(&b.y_lo, &b.y_hi);
  return b;
}

void Text(cairo_t* cr, double x, double y, const std::string& text, double size, bool bold, double align = 0.0) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, x - align * extents.x_advance, y);
  cairo_show_text(cr, text.c_str());
}

// The panel's frame, its title above it and its axes' labels.
void DrawFrameAndLabels(cairo_t* cr, const XyPanel& panel, double left, double top, double width, double height,
                        double ui) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, std::max(1.0, ui));
  cairo_rectangle(cr, left, top, width, height);
  cairo_stroke(cr);
  Text(cr, left, top - 8 * ui, panel.title, 13 * ui, true);
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  Text(cr, left + width, top + height + 30 * ui, panel.x_label, 11 * ui, false, 1.0);
  cairo_save(cr);
  // Rotate about the label's place (a move_to would not move the origin the
  // label is drawn from: it was drawn off the picture's top left corner).
  cairo_translate(cr, left - 42 * ui, top + height / 2);
  cairo_rotate(cr, -M_PI / 2);
  Text(cr, 0, 0, panel.y_label, 11 * ui, false, 0.5);
  cairo_restore(cr);
}

// The legend, top left inside the panel: a swatch and the label of each labelled series.
void DrawLegend(cairo_t* cr, const XyPanel& panel, double left, double top, double ui) {
  double legend_y = top + 16 * ui;
  for (const XySeries& s : panel.series) {
    if (s.label.empty()) continue;
    const auto& rgb = RobotColor(s.color);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_rectangle(cr, left + 8 * ui, legend_y - 8 * ui, 10 * ui, 8 * ui);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    Text(cr, left + 22 * ui, legend_y, s.label, 10 * ui, false);
    legend_y += 14 * ui;
  }
}

void DrawPanel(cairo_t* cr, const XyPanel& panel, double left, double top, double width, double height, double ui) {
  const Bounds b = BoundsOf(panel);
  auto x_px = [&](double x) { return left + (x - b.x_lo) / (b.x_hi - b.x_lo) * width; };
  auto y_px = [&](double y) { return top + height - (y - b.y_lo) / (b.y_hi - b.y_lo) * height; };
  cairo_set_line_width(cr, std::max(1.0, ui));
  const double x_spacing = TickSpacing(b.x_hi - b.x_lo, 6);
  const double y_spacing = TickSpacing(b.y_hi - b.y_lo, 5);
  for (double x = std::ceil(b.x_lo / x_spacing) * x_spacing; x <= b.x_hi + 1e-12; x += x_spacing) {
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, x_px(x), top);
    cairo_line_to(cr, x_px(x), top + height);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    Text(cr, x_px(x), top + height + 14 * ui, TickText(x, x_spacing), 10 * ui, false, 0.5);
  }
  for (double y = std::ceil(b.y_lo / y_spacing) * y_spacing; y <= b.y_hi + 1e-12; y += y_spacing) {
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, left, y_px(y));
    cairo_line_to(cr, left + width, y_px(y));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    Text(cr, left - 5 * ui, y_px(y) + 4 * ui, TickText(y, y_spacing), 10 * ui, false, 1.0);
  }
  cairo_save(cr);
  cairo_rectangle(cr, left, top, width, height);
  cairo_clip(cr);
  for (const XySeries& s : panel.series) {
    const auto& rgb = RobotColor(s.color);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, std::max(1.0, 1.8 * ui));
    if (s.style == XySeries::Style::kDots) {
      for (const auto& p : s.points) {
        cairo_arc(cr, x_px(p[0]), y_px(p[1]), 1.6 * ui, 0, 2 * M_PI);
        cairo_fill(cr);
      }
    } else if (s.style == XySeries::Style::kBars) {
      // Bars as wide as the closest two bin centres allow.
      double bin = 0.0;
      for (size_t i = 1; i < s.points.size(); ++i) {
        const double gap = std::abs(s.points[i][0] - s.points[i - 1][0]);
        if (gap > 0 && (bin == 0 || gap < bin)) bin = gap;
      }
      if (bin == 0) bin = 1.0;
      cairo_set_source_rgba(cr, rgb[0], rgb[1], rgb[2], 0.55);
      for (const auto& p : s.points) {
        const double x0 = x_px(p[0] - 0.45 * bin);
        const double x1 = x_px(p[0] + 0.45 * bin);
        cairo_rectangle(cr, x0, y_px(p[1]), x1 - x0, y_px(std::max(b.y_lo, 0.0)) - y_px(p[1]));
        cairo_fill(cr);
      }
    } else if (!s.points.empty()) {
      const double dash = 6 * ui;
      if (s.style == XySeries::Style::kDashedLine) cairo_set_dash(cr, &dash, 1, 0);
      cairo_move_to(cr, x_px(s.points.front()[0]), y_px(s.points.front()[1]));
      for (const auto& p : s.points) cairo_line_to(cr, x_px(p[0]), y_px(p[1]));
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
    }
  }
  cairo_restore(cr);
  DrawFrameAndLabels(cr, panel, left, top, width, height, ui);
  DrawLegend(cr, panel, left, top, ui);
}

}  // namespace

void XyPlot::Render(const std::vector<XyPanel>& panels, int columns, const std::string& title, const std::string& path,
                    RenderFormat format, int width_px) {
  if (panels.empty()) throw std::invalid_argument("nothing to plot: no panels");
  for (const XyPanel& panel : panels) {
    bool any = false;
    for (const XySeries& s : panel.series) any = any || !s.points.empty();
    if (!any) throw std::invalid_argument("the panel '" + panel.title + "' has no points to plot");
  }
  columns = std::max(1, columns);
  const int rows = static_cast<int>((panels.size() + static_cast<size_t>(columns) - 1) / static_cast<size_t>(columns));
  const double ui = width_px / 1200.0;
  const double cell_width = static_cast<double>(width_px) / columns;
  const double cell_height = 380 * ui;
  const double top = 40 * ui;
  const int height_px = static_cast<int>(std::ceil(top + rows * cell_height));
  PictureSurface surface(format, width_px, height_px);
  cairo_t* cr = surface.cr();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  Text(cr, 20 * ui, 24 * ui, title, 16 * ui, true);
  for (size_t i = 0; i < panels.size(); ++i) {
    const double cell_left = static_cast<double>(i % static_cast<size_t>(columns)) * cell_width;
    const double cell_top = top + static_cast<double>(i / static_cast<size_t>(columns)) * cell_height;
    DrawPanel(cr, panels[i], cell_left + 70 * ui, cell_top + 30 * ui, cell_width - 100 * ui, cell_height - 80 * ui, ui);
  }
  surface.Commit(path);
}

}  // namespace dream::render
