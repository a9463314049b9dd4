#pragma once

#include <optional>

#include "dream/render/viewport.h"
#include "dream/world/arena.h"

namespace dream::render {

/// Where the arena lands in a picture `width_px` wide: metres to pixels
/// (x right, y up in the world; y down in the picture), a margin round the
/// arena that holds its tick labels in metres, a legend row below it and room
/// for caption lines under the legend. Line widths and fonts grow
/// with ui_scale() so a 720 px video frame and a 1280 px picture look alike.
/// The frame (where the arena is drawn) keeps the arena's shape; with a
/// Viewport it shows that part of the world instead, zoomed to fit it whole.
class ArenaLayout {
 public:
  /// @param even_size rounds the height up to an even number (H.264 frames
  ///        need even sizes; the width must then be even too).
  /// @param viewport the part of the world the frame shows; none: the arena.
  /// @throws std::invalid_argument when width_px is below kMinWidthPx.
  ArenaLayout(int width_px, int caption_lines, bool even_size = false,
              const std::optional<Viewport>& viewport = std::nullopt);

  static constexpr int kMinWidthPx = 160;
  static constexpr int kMaxWidthPx = 8192;

  double px(double x_m) const { return margin_px_ + (x_m - visible_.x_min_m) * scale_; }
  double py(double y_m) const { return margin_px_ + (visible_.y_max_m - y_m) * scale_; }
  /// Pixels per metre in the frame (grows with a viewport's zoom).
  double scale() const { return scale_; }
  /// Pixels per metre of the whole arena in the frame: the legend's markers, drawn to this scale, stay put when zoomed.
  double frame_scale() const { return frame_scale_; }
  /// The world the frame shows: the arena, or the viewport widened in one
  /// direction to the frame's shape.
  const Viewport& visible() const { return visible_; }
  /// A viewport was given: drawings must be clipped to the frame.
  bool zoomed() const { return zoomed_; }
  /// The frame's edges, pixels from the left and top.
  double frame_left_px() const { return margin_px_; }
  double frame_top_px() const { return margin_px_; }
  double frame_right_px() const { return margin_px_ + arena_.width_m() * frame_scale_; }
  double frame_bottom_px() const { return margin_px_ + arena_.height_m() * frame_scale_; }
  /// Metres between grid lines (and tick labels): 0.5 for the arena, finer when zoomed in.
  double grid_step_m() const;
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
  double frame_scale_;
  double scale_;
  Viewport visible_;
  bool zoomed_;
  int height_px_;
};

}  // namespace dream::render
