#include "dream/world/realism_params.h"

#include <cmath>

#include "field_check.h"

namespace dream::sim {

using field_check::Fail;
using field_check::IsNonNegativeFinite;
using field_check::IsPositiveFinite;

RealismParams RealismParams::Ideal() { return RealismParams{}; }

namespace {

bool IsProbability(double value) { return value >= 0.0 && value <= 1.0; }
bool IsAtLeastOneFinite(double value) { return std::isfinite(value) && value >= 1.0; }

}  // namespace

const std::vector<RealismParams::Field>& RealismParams::Fields() {
  using P = RealismParams;
  static const std::vector<Field> fields = {
      {"pose_noise_m", &P::pose_noise_m, nullptr, IsNonNegativeFinite, ">= 0 m, finite"},
      {"pose_noise_rad", &P::pose_noise_rad, nullptr, IsNonNegativeFinite, ">= 0 rad, finite"},
      {"pose_quantum_m", &P::pose_quantum_m, nullptr, IsNonNegativeFinite, ">= 0 m, finite (0: not rounded)"},
      {"pose_quantum_rad", &P::pose_quantum_rad, nullptr, IsNonNegativeFinite, ">= 0 rad, finite (0: not rounded)"},
      {"pose_delay_steps", nullptr, &P::pose_delay_steps, nullptr, nullptr},
      {"tracking_dropout_probability", &P::tracking_dropout_probability, nullptr, IsProbability, "[0, 1]"},
      {"tracking_dropout_mean_steps", &P::tracking_dropout_mean_steps, nullptr, IsAtLeastOneFinite,
       ">= 1 step, finite (1: each step on its own)"},
      {"tracker_drop_s", &P::tracker_drop_s, nullptr, IsNonNegativeFinite,
       ">= 0 s, finite (0: the tracker never drops a robot)"},
      {"command_latency_steps", nullptr, &P::command_latency_steps, nullptr, nullptr},
      {"command_brake_s", &P::command_brake_s, nullptr, IsNonNegativeFinite, ">= 0 s, finite (0: never brake)"},
      {"dead_zone_v_mps", &P::dead_zone_v_mps, nullptr, IsNonNegativeFinite, ">= 0 m/s, finite (0: no dead zone)"},
      {"dead_zone_w_radps", &P::dead_zone_w_radps, nullptr, IsNonNegativeFinite,
       ">= 0 rad/s, finite (0: no dead zone)"},
      {"wheel_accel_limit_radps2", &P::wheel_accel_limit_radps2, nullptr, IsNonNegativeFinite,
       ">= 0 rad/s^2, finite (0: no limit)"},
      {"axle_length_m", &P::axle_length_m, nullptr, IsPositiveFinite, "> 0 m, finite"},
  };
  return fields;
}

// Each value's source is in docs/experiments.md ("Realism").
RealismParams RealismParams::Lab() {
  RealismParams lab;
  lab.pose_noise_m = 0.001;
  lab.pose_noise_rad = 0.005;
  lab.pose_quantum_m = 0.0;  // the tracker sends doubles (JSON), nothing is rounded
  lab.pose_quantum_rad = 0.0;
  lab.pose_delay_steps = 1;
  lab.tracking_dropout_probability = 0.01;
  lab.tracking_dropout_mean_steps = 1.0;  // how long the lab's dropouts last is not published
  lab.tracker_drop_s = 5.0;
  lab.command_latency_steps = 1;
  lab.command_brake_s = 0.5;
  lab.dead_zone_v_mps = 1e-4;
  lab.dead_zone_w_radps = 0.01;
  lab.wheel_accel_limit_radps2 = 100.0;
  lab.axle_length_m = 0.105;
  return lab;
}

const std::vector<std::string>& RealismParams::PresetNames() {
  static const std::vector<std::string> names{"ideal", "lab"};
  return names;
}

bool RealismParams::FromPreset(const std::string& name, RealismParams* params) {
  if (name == "ideal") {
    *params = Ideal();
  } else if (name == "lab") {
    *params = Lab();
  } else {
    return false;
  }
  return true;
}

bool RealismParams::IsIdeal() const { return *this == Ideal(); }

bool RealismParams::IsValid(std::string* error) const {
  for (const Field& field : Fields()) {
    if (field.steps != nullptr) {
      const int value = this->*field.steps;
      if (value < 0 || value > kMaxDelaySteps) {
        return Fail(error, field.key, value, "0.." + std::to_string(kMaxDelaySteps) + " steps");
      }
    } else if (!field.allows(this->*field.number)) {
      return Fail(error, field.key, this->*field.number, field.allowed);
    }
  }
  return true;
}

bool operator==(const RealismParams& a, const RealismParams& b) {
  for (const RealismParams::Field& field : RealismParams::Fields()) {
    if (field.number != nullptr ? a.*field.number != b.*field.number : a.*field.steps != b.*field.steps) return false;
  }
  return true;
}

}  // namespace dream::sim
