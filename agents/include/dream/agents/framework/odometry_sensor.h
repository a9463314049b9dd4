#pragma once

#include <cstdint>
#include <string>

#include "dream/agents/framework/noise_source.h"
#include "dream/agents/framework/sensor.h"

namespace dream::agents {

struct OdometrySensorParams {
  double noise_std = 0.0;  ///< std dev added to x (m), y (m) and theta (rad); >= 0
  bool IsValid(std::string* error) const;
};

/// The robot's own pose, plus gaussian noise on each coordinate.
class OdometrySensor final : public Sensor {
 public:
  /// @throws std::invalid_argument when params are invalid.
  OdometrySensor(const OdometrySensorParams& params, uint64_t seed);
  void Sense(const WorldSnapshot& world, Robot& robot) override;

 private:
  OdometrySensorParams params_;
  NoiseSource noise_;
};

}  // namespace dream::agents
