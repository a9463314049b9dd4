#pragma once

#include <string>

#include "dream/world/arena.h"

namespace dream::render {

/// The part of the world a video shows, in metres (x right, y up): what the
/// view's page shows after zoom and pan, and `dream render --viewport`. The
/// picture keeps the arena's shape, so the viewport is fitted into it, centred,
/// and a little more than it is shown in one direction (ArenaLayout::visible()).
struct Viewport {
  double x_min_m = 0.0;
  double y_min_m = 0.0;
  double x_max_m = 0.0;
  double y_max_m = 0.0;

  /// Narrowest side, metres: a viewport is at least a robot across.
  static constexpr double kMinSpanM = 0.1;
  /// How far past the arena's walls a viewport may reach, metres (the page
  /// shows robots up to 1 m outside).
  static constexpr double kMaxOutsideM = 2.0;

  double width_m() const { return x_max_m - x_min_m; }
  double height_m() const { return y_max_m - y_min_m; }

  /// "XMIN,YMIN,XMAX,YMAX" in metres ("-0.8,-0.5,0.4,0.3"), checked against `arena`.
  /// @throws std::invalid_argument naming --viewport and what is wrong.
  static Viewport Parse(const std::string& text, const world::Arena& arena = {});
  /// Finite, each side at least kMinSpanM, and within kMaxOutsideM of `arena`.
  /// @throws std::invalid_argument naming `what` (an option or a parameter) and the value.
  void Check(const world::Arena& arena, const std::string& what) const;
  /// "XMIN,YMIN,XMAX,YMAX" with millimetres kept ("-0.8,-0.5,0.4,0.3"): what Parse reads back.
  std::string Text() const;
};

}  // namespace dream::render
