#pragma once

#include <string>

#include "dream/agents/framework/noisy_sensor.h"

namespace dream::agents {

struct ObstacleSensorParams {
  double range_m = 1.0;    ///< reports obstacles whose closest point is within this distance; > 0
  double noise_std = 0.0;  ///< std dev added to each coordinate of a closest point, m; >= 0
  bool IsValid(std::string* error) const;
};

/// The closest point of every virtual obstacle within range (added for the
/// Voronoi experiment, where obstacles become virtual neighbours).
class ObstacleSensor final : public NoisySensor<ObstacleSensorParams> {
 public:
  using NoisySensor::NoisySensor;
  void Sense(const WorldSnapshot& world, Robot& robot) override;
};

}  // namespace dream::agents
