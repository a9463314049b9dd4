#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dream::agents {

/// A virtual rectangular obstacle as the world reports it.
struct ObstacleView {
  int id = 0;
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();  ///< world frame
  Eigen::Vector2d size_m = Eigen::Vector2d::Zero();    ///< width (x), height (y)
  Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();
};

/// The world at one step, as the world published it. Only sensors and radios
/// read it; a Robot never sees it (it knows what its accessories report).
struct WorldSnapshot {
  int64_t step = 0;
  std::vector<Eigen::Vector3d> poses;       ///< per robot: x m, y m, theta rad (world frame)
  std::vector<Eigen::Vector2d> velocities;  ///< per robot: v m/s, w rad/s driven during the last step
  std::vector<ObstacleView> obstacles;

  int num_robots() const { return static_cast<int>(poses.size()); }
};

}  // namespace dream::agents
