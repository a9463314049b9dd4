#pragma once

namespace dream::world {

// Where a virtual rectangular obstacle is at one step, as a world publishes it
// on DREAM_OBSTACLES: plain numbers, whether the world moves it (the
// simulator) or replays it (a lab replay).
struct ObstacleState {
  int id = 0;  // RectangleObstacleSpec::id
  double center_x_m = 0.0;
  double center_y_m = 0.0;
  double width_m = 0.0;   // extent along x
  double height_m = 0.0;  // extent along y
  double vx_mps = 0.0;    // velocity of the leg it travels now (0 when static)
  double vy_mps = 0.0;

  // True if the disc touches or overlaps the rectangle (the one arithmetic
  // for it: RectangleObstacle::IntersectsDisc uses it too).
  bool IntersectsDisc(double disc_x_m, double disc_y_m, double radius_m) const;
};

}  // namespace dream::world
