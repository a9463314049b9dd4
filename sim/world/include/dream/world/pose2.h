#pragma once

namespace dream::world {

// A planar robot pose in the world frame.
struct Pose2 {
  double x_m = 0.0;
  double y_m = 0.0;
  // Heading, counter-clockwise from +x. The world keeps it in [-pi, pi] after
  // every step (atan2 wrap), like the Robotarium.
  double theta_rad = 0.0;
};

}  // namespace dream::world
