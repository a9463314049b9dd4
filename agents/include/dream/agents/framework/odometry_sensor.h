#pragma once

#include <string>

#include "dream/agents/framework/noisy_sensor.h"

namespace dream::agents {

struct OdometrySensorParams {
  double noise_std = 0.0;  ///< std dev added to x (m), y (m) and theta (rad); >= 0
  bool IsValid(std::string* error) const;
};

/// The robot's own pose, plus gaussian noise on each coordinate.
class OdometrySensor final : public NoisySensor<OdometrySensorParams> {
 public:
  using NoisySensor::NoisySensor;
  void Sense(const WorldSnapshot& world, Robot& robot) override;
};

}  // namespace dream::agents
