#include "dream/render/arena_layout.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::render {
namespace {

constexpr double kReferenceWidthPx = 1280.0;  // ui_scale() == 1
constexpr double kMarginPx = 36.0;            // at ui_scale 1: room for the tick labels
constexpr double kLegendRowSpacing = 1.6;     // legend row height / caption font size, at least
constexpr double kLegendRowRobots = 2.5;      // legend row height / robot radius (markers are to scale), at least
constexpr double kCaptionLineSpacing = 1.45;  // line height / font size

}  // namespace

ArenaLayout::ArenaLayout(int width_px, int caption_lines, bool even_size, const std::optional<Viewport>& viewport)
    : width_px_(width_px),
      ui_scale_(width_px / kReferenceWidthPx),
      margin_px_(std::round(kMarginPx * std::max(ui_scale_, 0.5))),
      frame_scale_((width_px - 2 * margin_px_) / arena_.width_m()),
      scale_(frame_scale_),
      visible_{arena_.x_min_m, arena_.y_min_m, arena_.x_max_m, arena_.y_max_m},
      zoomed_(viewport.has_value()) {
  if (width_px < kMinWidthPx || width_px > kMaxWidthPx) {
    throw std::invalid_argument("picture width must be " + std::to_string(kMinWidthPx) + ".." +
                                std::to_string(kMaxWidthPx) + " px, got " + std::to_string(width_px));
  }
  if (viewport) {
    viewport->Check(arena_, "viewport");
    // The whole viewport fits, centred; the frame's other direction shows more.
    const double zoom = std::min(arena_.width_m() / viewport->width_m(), arena_.height_m() / viewport->height_m());
    scale_ = frame_scale_ * zoom;
    const double half_w = arena_.width_m() / zoom / 2;
    const double half_h = arena_.height_m() / zoom / 2;
    const double cx = (viewport->x_min_m + viewport->x_max_m) / 2;
    const double cy = (viewport->y_min_m + viewport->y_max_m) / 2;
    visible_ = {cx - half_w, cy - half_h, cx + half_w, cy + half_h};
  }
  const double legend_px = legend_row_px();
  const double captions_px = caption_lines > 0 ? 4 + caption_font_px() * kCaptionLineSpacing * caption_lines : 0;
  height_px_ = static_cast<int>(std::ceil(arena_.height_m() * frame_scale_ + 2 * margin_px_ + legend_px + captions_px));
  if (even_size && height_px_ % 2 != 0) ++height_px_;
}

double ArenaLayout::caption_font_px() const { return std::max(11.0, 14.0 * ui_scale_); }

double ArenaLayout::tick_font_px() const { return std::max(9.0, 11.0 * ui_scale_); }

double ArenaLayout::legend_row_px() const {
  return std::max(caption_font_px() * kLegendRowSpacing,
                  kLegendRowRobots * robotarium::RobotariumConstants::kRobotDiameterMeters / 2 * frame_scale_);
}

double ArenaLayout::legend_center_px() const { return frame_bottom_px() + margin_px_ * 0.6 + legend_row_px() / 2; }

double ArenaLayout::caption_baseline_px(int line) const {
  const double line_px = caption_font_px() * kCaptionLineSpacing;
  return frame_bottom_px() + margin_px_ * 0.6 + legend_row_px() + line_px * (line + 1) - caption_font_px() * 0.2;
}

double ArenaLayout::grid_step_m() const {
  // About four or more lines across the frame, on round numbers.
  const double span = std::min(visible_.width_m(), visible_.height_m());
  if (span >= 1.5) return 0.5;
  if (span >= 0.6) return 0.2;
  if (span >= 0.3) return 0.1;
  return 0.05;
}

}  // namespace dream::render
