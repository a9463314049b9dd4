#include "arena_canvas.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_set>

namespace dream::sim::render {
namespace {

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

constexpr double kCaptionLinePx = 20.0;

}  // namespace

const std::array<double, 3>& RobotColor(int robot_id) {
  return kColors[static_cast<size_t>(robot_id < 0 ? 0 : robot_id) % kColors.size()];
}

ArenaCanvas::ArenaCanvas(int width_px, int caption_lines)
    : scale_((width_px - 2 * 30.0) / Arena{}.width_m()),
      height_px_(static_cast<int>(std::lround(Arena{}.height_m() * scale_ + 2 * 30.0 + 4 + kCaptionLinePx * caption_lines))),
      surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width_px, height_px_), cairo_surface_destroy),
      cr_(cairo_create(surface_.get()), cairo_destroy) {
  cairo_t* c = cr_.get();
  cairo_set_source_rgb(c, 1, 1, 1);
  cairo_paint(c);
  // Half-metre grid, then the arena boundary.
  cairo_set_source_rgb(c, 0.9, 0.9, 0.9);
  cairo_set_line_width(c, 1.0);
  for (double x = -1.5; x <= 1.51; x += 0.5) {
    cairo_move_to(c, px(x), py(arena_.y_min_m));
    cairo_line_to(c, px(x), py(arena_.y_max_m));
  }
  for (double y = -1.0; y <= 1.01; y += 0.5) {
    cairo_move_to(c, px(arena_.x_min_m), py(y));
    cairo_line_to(c, px(arena_.x_max_m), py(y));
  }
  cairo_stroke(c);
  cairo_set_source_rgb(c, 0, 0, 0);
  cairo_set_line_width(c, 2.0);
  cairo_rectangle(c, px(arena_.x_min_m), py(arena_.y_max_m), arena_.width_m() * scale_, arena_.height_m() * scale_);
  cairo_stroke(c);
}

void ArenaCanvas::StrokePolyline(const std::vector<std::array<double, 2>>& points_px) {
  if (points_px.empty()) return;
  cairo_t* c = cr_.get();
  cairo_set_line_cap(c, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(c, CAIRO_LINE_JOIN_ROUND);
  auto key = [](const std::array<double, 2>& a, const std::array<double, 2>& b) {
    auto pixel = [](double v) { return static_cast<uint64_t>(static_cast<uint16_t>(std::lround(v) + 16384)); };
    uint64_t from = pixel(a[0]) << 16 | pixel(a[1]);
    uint64_t to = pixel(b[0]) << 16 | pixel(b[1]);
    if (from > to) std::swap(from, to);
    return from << 32 | to;
  };
  std::unordered_set<uint64_t> drawn;
  std::array<double, 2> last = points_px.front();
  bool pen_down = false;
  cairo_move_to(c, last[0], last[1]);
  for (size_t i = 1; i < points_px.size(); ++i) {
    const std::array<double, 2>& point = points_px[i];
    const double dx = point[0] - last[0];
    const double dy = point[1] - last[1];
    if (dx * dx + dy * dy < 1.0 && i + 1 < points_px.size()) continue;
    if (drawn.insert(key(last, point)).second) {
      if (!pen_down) cairo_move_to(c, last[0], last[1]);
      cairo_line_to(c, point[0], point[1]);
      pen_down = true;
    } else {
      pen_down = false;
    }
    last = point;
  }
  cairo_stroke(c);
}

void ArenaCanvas::Caption(int line, const std::string& text) {
  cairo_t* c = cr_.get();
  cairo_set_source_rgb(c, 0.2, 0.2, 0.2);
  cairo_select_font_face(c, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(c, 14.0);
  cairo_move_to(c, margin_px_, py(arena_.y_min_m) + margin_px_ + 14.0 + kCaptionLinePx * line);
  cairo_show_text(c, text.c_str());
}

void ArenaCanvas::WritePng(const std::string& png_path) {
  cairo_surface_flush(surface_.get());
  const std::string temp = png_path + ".tmp." + std::to_string(::getpid());
  if (cairo_surface_write_to_png(surface_.get(), temp.c_str()) != CAIRO_STATUS_SUCCESS ||
      std::rename(temp.c_str(), png_path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw std::runtime_error("cannot write the picture " + png_path + " (does the folder exist?)");
  }
}

}  // namespace dream::sim::render
