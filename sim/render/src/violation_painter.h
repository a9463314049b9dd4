#pragma once

#include <cairo.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "dream/render/arena_layout.h"
#include "dream/world/located_violation.h"

namespace dream::render {

/// The red of violation marks.
inline constexpr double kViolationRed[3] = {0.84, 0.08, 0.08};

/// A violation's mark at pixel (x, y): a red ring with a cross, `radius_px`
/// wide, with opacity `alpha` (also the legend's marker).
void ViolationRing(cairo_t* cr, double x, double y, double radius_px, double line_px, double alpha);

/// Marks located violations where they happened: a red ring with a cross
/// round the robot (or the middle of a colliding pair) and a small
/// "k=<first step>" label beside it. Marks closer than half a ring are one
/// ring, labelled "k=<earliest> +<how many more>"; labels are placed at a
/// corner of their ring where they overlap no label already placed (inside
/// the picture), and left out where every corner is taken, so many marks
/// stay readable.
class ViolationPainter {
 public:
  ViolationPainter(cairo_t* cr, const ArenaLayout& layout) : cr_(cr), layout_(layout) {}

  /// Marks every violation (a picture of the whole run), or with `now_step`
  /// (a video frame) those begun by then, the ones over by then
  /// (last_step < now_step) faded. Returns how many labels found a place.
  int Mark(const std::vector<world::LocatedViolation>& violations, std::optional<int64_t> now_step = {}) const;

  /// The ring's radius in pixels: round a colliding pair (0.135 m apart, 0.11 m wide).
  double RingRadiusPx() const;

 private:
  /// Where a ring goes, for one violation or several at one place.
  struct Spot {
    double x = 0;  // pixels
    double y = 0;
    int64_t first_step = 0;  // the earliest of its violations
    int64_t last_step = 0;   // the latest step of its violations (an episode's end)
    int others = 0;          // violations there besides the first
    bool going_on = true;    // a video frame: one of them still lasts
  };
  std::vector<Spot> Spots(const std::vector<world::LocatedViolation>& violations,
                          std::optional<int64_t> now_step) const;

  cairo_t* cr_;
  const ArenaLayout& layout_;
};

}  // namespace dream::render
