#pragma once

#include <string>
#include <vector>

#include "dream/lcm/drawn_shape.h"

namespace dream {
class drawing_t;
}

namespace dream::lcm {

/// A drawing_t (DREAM_DRAW_<id>) checked against its type's bounds and read
/// as shapes: what the world checks before recording one, and what `dream
/// view` and `dream render` read. lcm::Decode already bounded the arrays
/// (drawing_t::MAX_SHAPES, MAX_POINTS, MAX_ALL_TEXT_BYTES); this checks what
/// the wire cannot say: the kinds, each shape's points and text against the
/// arrays, numbers finite and inside the bounds below, text UTF-8.
class DrawingShapes {
 public:
  /// Coordinates past this, metres, are no drawing of an arena of 3.2 m.
  static constexpr double kMaxAbsCoordinateM = 100.0;
  /// Widths, radii and text heights past this, metres.
  static constexpr double kMaxSizeM = 10.0;

  /// Why `drawing` is no drawing to show, or "" when it is one.
  static std::string Problem(const drawing_t& drawing);

  /// The shapes of `drawing`, or nothing when Problem() is not "".
  static std::vector<DrawnShape> Of(const drawing_t& drawing);
};

}  // namespace dream::lcm
