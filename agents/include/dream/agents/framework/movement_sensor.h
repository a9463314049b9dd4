#pragma once

#include <cmath>
#include <string>

#include "dream/agents/framework/noisy_sensor.h"

namespace dream::agents {

struct MovementSensorParams {
  double range_m = 1.0;                 ///< detects neighbours up to this distance; > 0
  double direction_rad = 0.0;           ///< where the field of view points, relative to the robot's heading
  double field_of_view_rad = 2 * M_PI;  ///< full opening angle, (0, 2 pi] (6.2832 counts as 2 pi)
  double noise_std = 0.0;               ///< std dev added to distance, bearing and velocity; >= 0
  /// Neighbour velocities are those of the point this far ahead of the
  /// centre (the thesis's 0.05 m), from the velocity the neighbour drove with.
  double velocity_point_ahead_m = 0.05;
  bool IsValid(std::string* error) const;
};

/// Neighbours within range and field of view: distance, world-frame bearing
/// from this robot to the neighbour, and velocity. (The thesis reported the
/// angle from the neighbour to this robot and compensated inside HRVO; here
/// the bearing means what it says.)
class MovementSensor final : public NoisySensor<MovementSensorParams> {
 public:
  using NoisySensor::NoisySensor;
  void Sense(const WorldSnapshot& world, Robot& robot) override;
};

}  // namespace dream::agents
