#pragma once

#include "dream/world/arena.h"

namespace dream::render {

/// Where the arena lands in a picture `width_px` wide: metres to pixels
/// (x right, y up in the world; y down in the picture), a margin round the
/// arena that holds its tick labels in metres, a legend row below it and room
/// for caption lines under the legend. Line widths and fonts grow
/// with ui_scale() so a 720 px video frame and a 1280 px picture look alike.
class ArenaLayout {
 public:
  /// @param even_size rounds the height up to an even number (H.264 frames
  ///        need even sizes; the width must then be even too).
  /// @throws std::invalid_argument when width_px is below kMinWidthPx.
  ArenaLayout(int width_px, int caption_lines, bool even_size = false);

  static constexpr int kMinWidthPx = 160;
  static constexpr int kMaxWidthPx = 8192;

  double px(double x_m) const { return margin_px_ + (x_m - arena_.x_min_m) * scale_; }
  double py(double y_m) const { return margin_px_ + (arena_.y_max_m - y_m) * scale_; }
  /// Pixels per metre.
  double scale() const { return scale_; }
  /// 1 for a 1280 px wide picture.
  double ui_scale() const { return ui_scale_; }
  int width_px() const { return width_px_; }
  int height_px() const { return height_px_; }
  /// Caption font size, pixels (readable in small video frames too).
  double caption_font_px() const;
  /// Tick label font size, pixels (smaller than the caption).
  double tick_font_px() const;
  /// Height of the legend row, pixels (its robot markers are to scale).
  double legend_row_px() const;
  /// Middle of the legend row (between the x tick labels and the captions), pixels from the top.
  double legend_center_px() const;
  /// Baseline of caption line `line` (0 = first), pixels from the top.
  double caption_baseline_px(int line) const;
  const world::Arena& arena() const { return arena_; }

 private:
  world::Arena arena_{};
  int width_px_;
  double ui_scale_;
  double margin_px_;
  double scale_;
  int height_px_;
};

}  // namespace dream::render
