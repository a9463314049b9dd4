#pragma once

#include <cstdint>

#include "dream/agents/framework/noise_source.h"
#include "dream/agents/framework/params_check.h"
#include "dream/agents/framework/sensor.h"

namespace dream::agents {

/// What every built-in sensor is made of: its params, checked once when it is
/// built, and its own seeded noise.
template <typename Params>
class NoisySensor : public Sensor {
 public:
  /// @throws std::invalid_argument when params are invalid.
  NoisySensor(const Params& params, uint64_t seed) : params_(CheckedParams(params)), noise_(seed) {}

 protected:
  const Params& params() const { return params_; }
  NoiseSource& noise() { return noise_; }

 private:
  Params params_;
  NoiseSource noise_;
};

}  // namespace dream::agents
