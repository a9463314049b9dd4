#pragma once

#include <Eigen/Core>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::agents {

/// The Robotarium arena's lower-left and upper-right corners in the world
/// frame: the defaults of every part that keeps robots inside it.
inline Eigen::Vector2d RobotariumArenaMin() {
  return {robotarium::RobotariumConstants::kArenaXMinMeters, robotarium::RobotariumConstants::kArenaYMinMeters};
}
inline Eigen::Vector2d RobotariumArenaMax() {
  return {robotarium::RobotariumConstants::kArenaXMaxMeters, robotarium::RobotariumConstants::kArenaYMaxMeters};
}

}  // namespace dream::agents
