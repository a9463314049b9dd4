#pragma once

namespace dream::barriers {

/// The rectangle a barrier with boundary keeps robots in (rps's
/// `boundary_points` = [x_min, x_max, y_min, y_max]), metres.
struct BoundaryBox {
  double x_min_m = 0.0;
  double x_max_m = 0.0;
  double y_min_m = 0.0;
  double y_max_m = 0.0;
};

}  // namespace dream::barriers
