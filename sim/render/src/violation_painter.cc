#include "violation_painter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace dream::render {
namespace {

constexpr double kRingRadiusM = 0.13;  // round a colliding pair: 0.135 / 2 + 0.055, rounded up

struct Box {
  double x0, y0, x1, y1;
  bool Overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

}  // namespace

void ViolationRing(cairo_t* cr, double x, double y, double radius_px, double line_px, double alpha) {
  cairo_set_source_rgba(cr, kViolationRed[0], kViolationRed[1], kViolationRed[2], alpha);
  cairo_set_line_width(cr, line_px);
  cairo_new_sub_path(cr);
  cairo_arc(cr, x, y, radius_px, 0, 2 * 3.14159265358979323846);
  cairo_stroke(cr);
  const double arm = radius_px * 0.3;
  cairo_move_to(cr, x - arm, y - arm);
  cairo_line_to(cr, x + arm, y + arm);
  cairo_move_to(cr, x - arm, y + arm);
  cairo_line_to(cr, x + arm, y - arm);
  cairo_stroke(cr);
}

double ViolationPainter::RingRadiusPx() const { return std::max(6.0, kRingRadiusM * layout_.scale()); }

std::vector<ViolationPainter::Spot> ViolationPainter::Spots(const std::vector<world::LocatedViolation>& violations,
                                                            std::optional<int64_t> now_step) const {
  // Marks closer than half a ring would hide each other: one ring for them,
  // labelled with the earliest first step and how many more are there.
  const double merge_px = RingRadiusPx() * 0.5;
  std::vector<Spot> spots;
  for (const world::LocatedViolation& v : violations) {
    if (now_step && v.first_step > *now_step) continue;
    const double x = layout_.px(v.x_m);
    const double y = layout_.py(v.y_m);
    const bool going_on = !now_step || v.last_step >= *now_step;
    auto near = std::find_if(spots.begin(), spots.end(),
                             [&](const Spot& spot) { return std::hypot(spot.x - x, spot.y - y) < merge_px; });
    if (near == spots.end()) {
      spots.push_back({x, y, v.first_step, v.last_step, 0, going_on});
    } else {
      near->first_step = std::min(near->first_step, v.first_step);
      near->last_step = std::max(near->last_step, v.last_step);
      ++near->others;
      near->going_on = near->going_on || going_on;
    }
  }
  return spots;
}

int ViolationPainter::Mark(const std::vector<world::LocatedViolation>& violations,
                           std::optional<int64_t> now_step) const {
  const double radius = RingRadiusPx();
  const double line = std::max(1.5, 2.0 * layout_.ui_scale());
  const std::vector<Spot> spots = Spots(violations, now_step);
  for (const Spot& spot : spots) ViolationRing(cr_, spot.x, spot.y, radius, line, spot.going_on ? 1.0 : 0.45);
  // Labels after every ring, so no ring covers a label.
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr_, std::max(9.0, layout_.caption_font_px() * 0.8));
  std::vector<Box> taken;
  int placed = 0;
  for (const Spot& spot : spots) {
    // An episode as its steps, "k=82-239"; "+2" for the others at the same spot.
    char steps[48];
    if (spot.last_step > spot.first_step && !now_step) {
      std::snprintf(steps, sizeof(steps), "k=%lld-%lld", static_cast<long long>(spot.first_step),
                    static_cast<long long>(spot.last_step));
    } else {
      std::snprintf(steps, sizeof(steps), "k=%lld", static_cast<long long>(spot.first_step));
    }
    char text[64];
    if (spot.others > 0) {
      std::snprintf(text, sizeof(text), "%s +%d", steps, spot.others);
    } else {
      std::snprintf(text, sizeof(text), "%s", steps);
    }
    cairo_text_extents_t extents;
    cairo_text_extents(cr_, text, &extents);
    const double x = spot.x;
    const double y = spot.y;
    const double w = extents.x_advance;
    const double h = extents.height + 2;
    // Right above, right below, left above, left below the ring.
    const std::array<std::array<double, 2>, 4> corners = {{{x + radius * 0.8, y - radius * 0.8 - h},
                                                           {x + radius * 0.8, y + radius * 0.8},
                                                           {x - radius * 0.8 - w, y - radius * 0.8 - h},
                                                           {x - radius * 0.8 - w, y + radius * 0.8}}};
    for (const std::array<double, 2>& corner : corners) {
      const Box box{corner[0], corner[1], corner[0] + w, corner[1] + h};
      if (box.x0 < 0 || box.y0 < 0 || box.x1 > layout_.width_px() || box.y1 > layout_.height_px()) continue;
      if (std::any_of(taken.begin(), taken.end(), [&](const Box& t) { return t.Overlaps(box); })) continue;
      taken.push_back(box);
      // A white halo keeps the label readable over tracks and grid lines.
      cairo_move_to(cr_, box.x0, box.y1 - 1);
      cairo_text_path(cr_, text);
      cairo_set_source_rgb(cr_, 1, 1, 1);
      cairo_set_line_width(cr_, 3.0);
      cairo_stroke(cr_);
      cairo_move_to(cr_, box.x0, box.y1 - 1);
      cairo_set_source_rgb(cr_, kViolationRed[0], kViolationRed[1], kViolationRed[2]);
      cairo_show_text(cr_, text);
      ++placed;
      break;
    }
  }
  return placed;
}

}  // namespace dream::render
