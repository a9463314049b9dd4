#include "dream/render/metric_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "arena_painter.h"
#include "dream/robotarium/robotarium_constants.h"
#include "picture_surface.h"
#include "plot_ticks.h"

namespace dream::render {
namespace {

constexpr double kStepS = robotarium::RobotariumConstants::kTimeStepSeconds;

struct Range {
  double lo;
  double hi;
};

// Values always show from 0 when they are all of one sign and 0 is not far
// off, so a falling error looks like it falls to zero.
Range ValueRange(const MetricSeries& series) {
  double lo = series.points.front()[1];
  double hi = lo;
  for (const auto& point : series.points) {
    lo = std::min(lo, point[1]);
    hi = std::max(hi, point[1]);
  }
  if (series.limit) {
    lo = std::min(lo, *series.limit);
    hi = std::max(hi, *series.limit);
  }
  if (lo >= 0 && lo < 0.5 * hi) lo = 0;
  if (hi - lo < 1e-12) {
    const double pad = std::max(std::abs(hi) * 0.1, 1e-3);
    lo -= pad;
    hi += pad;
  }
  const double pad = (hi - lo) * 0.05;
  return {lo == 0 ? 0 : lo - pad, hi + pad};
}

// One metric's panel: where it lies on the picture and the ranges it shows.
struct Panel {
  cairo_t* cr;
  double ui;
  double left;
  double plot_width;
  double y0;  // its top
  double height;
  Range time;
  Range values;

  double XOfStep(double step) const { return left + (step * kStepS - time.lo) / (time.hi - time.lo) * plot_width; }
  double YOf(double value) const { return y0 + height - (value - values.lo) / (values.hi - values.lo) * height; }
};

// The time the series span (at least one step); throws when one has no points.
Range TimeRange(const std::vector<MetricSeries>& series) {
  double first_step = series.front().points.empty() ? 0 : series.front().points.front()[0];
  double last_step = first_step;
  for (const MetricSeries& s : series) {
    if (s.points.empty()) throw std::invalid_argument("the metric " + s.name + " has no points to plot");
    first_step = std::min(first_step, s.points.front()[0]);
    last_step = std::max(last_step, s.points.back()[0]);
  }
  return {first_step * kStepS, std::max(last_step, first_step + 1) * kStepS};
}

// Grid lines with their value labels (left) and time labels (below).
void DrawGridAndTicks(const Panel& panel, double x_spacing, bool last) {
  cairo_t* cr = panel.cr;
  const double ui = panel.ui;
  const double left = panel.left;
  const double plot_width = panel.plot_width;
  const Range& time = panel.time;
  const Range& values = panel.values;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 11 * ui);
  cairo_set_line_width(cr, std::max(1.0, ui));
  const double y_spacing = TickSpacing(values.hi - values.lo, 4);
  for (double v = std::ceil(values.lo / y_spacing) * y_spacing; v <= values.hi + 1e-12; v += y_spacing) {
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, left, panel.YOf(v));
    cairo_line_to(cr, left + plot_width, panel.YOf(v));
    cairo_stroke(cr);
    const std::string text = TickText(v, y_spacing);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_move_to(cr, left - 6 * ui - extents.x_advance, panel.YOf(v) + extents.height / 2);
    cairo_show_text(cr, text.c_str());
  }
  for (double t = std::ceil(time.lo / x_spacing) * x_spacing; t <= time.hi + 1e-9; t += x_spacing) {
    const double x = left + (t - time.lo) / (time.hi - time.lo) * plot_width;
    cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo_move_to(cr, x, panel.y0);
    cairo_line_to(cr, x, panel.y0 + panel.height);
    cairo_stroke(cr);
    const std::string text = TickText(t, x_spacing);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_move_to(cr, x - extents.x_advance / 2, panel.y0 + panel.height + 15 * ui);
    cairo_show_text(cr, text.c_str());
  }
  if (last) {
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_move_to(cr, left + plot_width - 60 * ui, panel.y0 + panel.height + 32 * ui);
    cairo_show_text(cr, "time (s)");
  }
}

// The series' limit as a dashed red line with its label.
void DrawLimit(const Panel& panel, double limit, const std::string& label) {
  cairo_t* cr = panel.cr;
  const double dash = 6 * panel.ui;
  cairo_set_dash(cr, &dash, 1, 0);
  cairo_set_source_rgb(cr, 0.84, 0.15, 0.16);
  cairo_move_to(cr, panel.left, panel.YOf(limit));
  cairo_line_to(cr, panel.left + panel.plot_width, panel.YOf(limit));
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_move_to(cr, panel.left + 6 * panel.ui, panel.YOf(limit) - 4 * panel.ui);
  cairo_show_text(cr, label.c_str());
}

// The series' values as a line in the color of panel `index` (a dot when one).
void DrawCurve(const Panel& panel, const MetricSeries& s, size_t index) {
  cairo_t* cr = panel.cr;
  const double ui = panel.ui;
  const auto& rgb = RobotColor(static_cast<int>(index));
  cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
  cairo_set_line_width(cr, std::max(1.0, 1.8 * ui));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_move_to(cr, panel.XOfStep(s.points.front()[0]), panel.YOf(s.points.front()[1]));
  for (const auto& point : s.points) cairo_line_to(cr, panel.XOfStep(point[0]), panel.YOf(point[1]));
  if (s.points.size() == 1) {
    cairo_arc(cr, panel.XOfStep(s.points.front()[0]), panel.YOf(s.points.front()[1]), 3 * ui, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  cairo_stroke(cr);
}

// The panel's frame and, above it, the series' name.
void DrawFrameAndName(const Panel& panel, const std::string& name) {
  cairo_t* cr = panel.cr;
  const double ui = panel.ui;
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, std::max(1.0, ui));
  cairo_rectangle(cr, panel.left, panel.y0, panel.plot_width, panel.height);
  cairo_stroke(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 13 * ui);
  cairo_move_to(cr, panel.left, panel.y0 - 8 * ui);
  cairo_show_text(cr, name.c_str());
}

}  // namespace

void MetricPlot::Render(const std::vector<MetricSeries>& series, const std::string& title, const std::string& path,
                        RenderFormat format, int width_px) {
  if (series.empty()) throw std::invalid_argument("nothing to plot: no metric series");
  const Range time = TimeRange(series);

  const double ui = width_px / 1000.0;
  const double left = 80 * ui;
  const double right = 20 * ui;
  const double top = 60 * ui;  // the title, then the first panel's name
  const double panel_height = 170 * ui;
  const double panel_gap = 50 * ui;  // tick labels below a panel, the next panel's name above it
  const int height_px =
      static_cast<int>(std::ceil(top + static_cast<double>(series.size()) * (panel_height + panel_gap) + 20 * ui));
  PictureSurface surface(format, width_px, height_px);
  cairo_t* cr = surface.cr();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 16 * ui);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_move_to(cr, left, 22 * ui);
  cairo_show_text(cr, title.c_str());

  const double plot_width = width_px - left - right;
  const double x_spacing = TickSpacing(time.hi - time.lo, 8);
  for (size_t p = 0; p < series.size(); ++p) {
    const MetricSeries& s = series[p];
    const double y0 = top + static_cast<double>(p) * (panel_height + panel_gap);
    const Panel panel{cr, ui, left, plot_width, y0, panel_height, time, ValueRange(s)};
    DrawGridAndTicks(panel, x_spacing, p + 1 == series.size());
    if (s.limit) DrawLimit(panel, *s.limit, s.limit_label);
    DrawCurve(panel, s, p);
    DrawFrameAndName(panel, s.name);
  }
  surface.Commit(path);
}

}  // namespace dream::render
