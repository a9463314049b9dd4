#pragma once

#include <Eigen/Core>

namespace dream::agents {

/// One neighbour as HRVO needs it. Both vectors are in the world frame.
struct HrvoNeighbour {
  /// Neighbour's centre minus own centre, m. (A MovementReading's
  /// NeighbourDetection::RelativePosition() gives exactly this.)
  Eigen::Vector2d relative_position_m = Eigen::Vector2d::Zero();
  /// Neighbour's velocity, m/s. The thesis reports the velocity of the point
  /// 0.05 m ahead of the neighbour's centre, from its last command.
  Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();
};

}  // namespace dream::agents
