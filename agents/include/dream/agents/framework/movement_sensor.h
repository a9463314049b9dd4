#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "dream/agents/framework/noise_source.h"
#include "dream/agents/framework/sensor.h"

namespace dream::agents {

struct MovementSensorParams {
  double range_m = 1.0;                  ///< detects neighbours up to this distance; > 0
  double direction_rad = 0.0;            ///< where the field of view points, relative to the robot's heading
  double field_of_view_rad = 2 * M_PI;   ///< full opening angle, (0, 2 pi] (6.2832 counts as 2 pi)
  double noise_std = 0.0;                ///< std dev added to distance, bearing and velocity; >= 0
  /// Neighbour velocities are those of the point this far ahead of the
  /// centre (the thesis's 0.05 m), from the velocity the neighbour drove with.
  double velocity_point_ahead_m = 0.05;
  bool IsValid(std::string* error) const;
};

/// Neighbours within range and field of view: distance, world-frame bearing
/// from this robot to the neighbour, and velocity. (The thesis reported the
/// angle from the neighbour to this robot and compensated inside HRVO; here
/// the bearing means what it says.)
class MovementSensor final : public Sensor {
 public:
  /// @throws std::invalid_argument when params are invalid.
  MovementSensor(const MovementSensorParams& params, uint64_t seed);
  void Sense(const WorldSnapshot& world, Robot& robot) override;

 private:
  MovementSensorParams params_;
  NoiseSource noise_;
};

}  // namespace dream::agents
