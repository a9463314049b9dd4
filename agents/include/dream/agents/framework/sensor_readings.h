#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <vector>

namespace dream::agents {

// What sensors hand a Robot. Readings carry the step they were taken at;
// angles and positions are in the world frame, as the thesis's sensors report.

/// Own pose, with the odometry's noise.
struct OdometryReading {
  int64_t step = 0;
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();  ///< x m, y m, theta rad
};

/// One neighbour seen by a MovementSensor.
struct NeighbourDetection {
  double distance_m = 0.0;                                 ///< centre to centre
  double bearing_rad = 0.0;                                ///< world-frame direction from this robot to the neighbour
  Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();  ///< of the point 0.05 m ahead of its centre, world frame

  /// Neighbour centre minus own centre, world frame.
  Eigen::Vector2d RelativePosition() const {
    return distance_m * Eigen::Vector2d(std::cos(bearing_rad), std::sin(bearing_rad));
  }
};

/// Neighbours within range and field of view.
struct MovementReading {
  int64_t step = 0;
  std::vector<NeighbourDetection> neighbours;
};

/// An obstacle's rectangle as an obstacle sensor sees it (axis-aligned).
struct ObstacleRectangle {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();  ///< world frame
  Eigen::Vector2d size_m = Eigen::Vector2d::Zero();    ///< width (x), height (y)
};

/// Closest points of obstacles within range (one per obstacle).
struct ObstacleReading {
  int64_t step = 0;
  std::vector<Eigen::Vector2d> closest_points_m;  ///< world frame
  /// The same obstacles' rectangles, in the same order, shifted by the same
  /// noise as their closest points (what the free space around the robot
  /// is, e.g. for coverage).
  std::vector<ObstacleRectangle> rectangles;
};

}  // namespace dream::agents
