#include "dream/world/realism_params.h"

#include <cmath>

#include "field_check.h"

namespace dream::world {

using field_check::Fail;
using field_check::IsNonNegativeFinite;
using field_check::IsPositiveFinite;

RealismParams RealismParams::Ideal() { return RealismParams{}; }

namespace {

bool IsProbability(double value) { return value >= 0.0 && value <= 1.0; }
bool IsAtLeastOneFinite(double value) { return std::isfinite(value) && value >= 1.0; }
bool IsGain(double value) { return value >= RealismParams::kMinGain && value <= RealismParams::kMaxGain; }
bool IsSpread(double value) { return value >= 0.0 && value <= 0.5; }
bool IsDrift(double value) { return std::isfinite(value) && std::abs(value) <= 1.0; }
bool IsDriftSpread(double value) { return value >= 0.0 && value <= 1.0; }
bool IsLag(double value) { return value >= 0.0 && value <= 5.0; }
bool IsStartup(double value) { return value >= 0.0 && value <= 1.0; }
bool IsOverrun(double value) { return value >= 0.0 && value <= 1.0; }
bool IsStall(double value) { return value >= 0.0 && value <= RealismParams::kMaxStallS; }

}  // namespace

const std::vector<RealismParams::Field>& RealismParams::Fields() {
  using P = RealismParams;
  static const std::vector<Field> fields = {
      {"pose_noise_m", &P::pose_noise_m, nullptr, IsNonNegativeFinite, ">= 0 m, finite"},
      {"pose_noise_rad", &P::pose_noise_rad, nullptr, IsNonNegativeFinite, ">= 0 rad, finite"},
      {"pose_noise_moving_factor", &P::pose_noise_moving_factor, nullptr, IsAtLeastOneFinite,
       ">= 1, finite (1: the same noise moving as at rest)"},
      {"pose_quantum_m", &P::pose_quantum_m, nullptr, IsNonNegativeFinite, ">= 0 m, finite (0: not rounded)"},
      {"pose_quantum_rad", &P::pose_quantum_rad, nullptr, IsNonNegativeFinite, ">= 0 rad, finite (0: not rounded)"},
      {"pose_delay_steps", nullptr, &P::pose_delay_steps, nullptr, nullptr},
      {"tracking_dropout_probability", &P::tracking_dropout_probability, nullptr, IsProbability, "[0, 1]"},
      {"tracking_dropout_at_rest_factor", &P::tracking_dropout_at_rest_factor, nullptr, IsAtLeastOneFinite,
       ">= 1, finite (1: as often at rest as moving)"},
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
      {"motor_lag_s", &P::motor_lag_s, nullptr, IsLag, "[0, 5] s (0: no lag)"},
      {"motor_startup_m", &P::motor_startup_m, nullptr, IsStartup, "[0, 1] m (0: slow commands start as fast)"},
      {"linear_gain_mean", &P::linear_gain_mean, nullptr, IsGain, "[0.5, 1.5]"},
      {"linear_gain_spread", &P::linear_gain_spread, nullptr, IsSpread, "[0, 0.5] (a standard deviation)"},
      {"angular_gain_mean", &P::angular_gain_mean, nullptr, IsGain, "[0.5, 1.5]"},
      {"angular_gain_spread", &P::angular_gain_spread, nullptr, IsSpread, "[0, 0.5] (a standard deviation)"},
      {"heading_drift_mean_radps", &P::heading_drift_mean_radps, nullptr, IsDrift, "[-1, 1] rad/s"},
      {"heading_drift_spread_radps", &P::heading_drift_spread_radps, nullptr, IsDriftSpread,
       "[0, 1] rad/s (a standard deviation)"},
      {"step_overrun_mean_s", &P::step_overrun_mean_s, nullptr, IsOverrun, "[0, 1] s (0: every step on time)"},
      {"loop_stall_probability", &P::loop_stall_probability, nullptr, IsProbability, "[0, 1] per step"},
      {"loop_stall_max_s", &P::loop_stall_max_s, nullptr, IsStall, "[0, 10] s"},
      {"axle_length_m", &P::axle_length_m, nullptr, IsPositiveFinite, "> 0 m, finite"},
  };
  return fields;
}

// Each value's source is in docs/experiments.md ("Realism"): measured on real
// GRITSbot X runs of the Robotarium (issue 22) where the data determine it.
RealismParams RealismParams::Lab() {
  RealismParams lab;
  lab.pose_noise_m = 0.00033;   // at rest; 0.6 mm moving
  lab.pose_noise_rad = 0.0045;  // at rest; 0.008 rad moving
  lab.pose_noise_moving_factor = 1.8;
  lab.pose_quantum_m = 0.0;      // x, y unrounded
  lab.pose_quantum_rad = 0.001;  // every heading a multiple of 0.001 rad
  lab.pose_delay_steps = 1;
  lab.tracking_dropout_probability = 0.0008;  // 0.3 % of moving robot-steps stale
  lab.tracking_dropout_at_rest_factor = 5.0;  // 1.5 % at rest
  lab.tracking_dropout_mean_steps = 4.0;
  lab.tracker_drop_s = 5.0;
  lab.command_latency_steps = 3;
  lab.command_brake_s = 0.5;
  lab.dead_zone_v_mps = 1e-4;
  lab.dead_zone_w_radps = 0.01;
  lab.wheel_accel_limit_radps2 = 0.0;  // the lag below models the wheels' response
  lab.motor_lag_s = 0.136;
  lab.motor_startup_m = 0.018;
  lab.linear_gain_mean = 0.99;
  lab.linear_gain_spread = 0.035;
  lab.angular_gain_mean = 1.009;
  lab.angular_gain_spread = 0.03;
  lab.heading_drift_mean_radps = -0.011;
  lab.heading_drift_spread_radps = 0.007;
  lab.step_overrun_mean_s = 0.0009;
  lab.loop_stall_probability = 0.0005;
  lab.loop_stall_max_s = 0.7;
  lab.axle_length_m = 0.105;
  return lab;
}

// The lab preset before issue 22 fitted it to real runs: estimates from the
// lab's published sources, kept so a model can be held against it.
RealismParams RealismParams::LabV1() {
  RealismParams lab;
  lab.pose_noise_m = 0.001;
  lab.pose_noise_rad = 0.005;
  lab.pose_delay_steps = 1;
  lab.tracking_dropout_probability = 0.01;
  lab.tracking_dropout_mean_steps = 1.0;
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
  static const std::vector<std::string> names{"ideal", "lab", "lab_v1"};
  return names;
}

bool RealismParams::FromPreset(const std::string& name, RealismParams* params) {
  if (name == "ideal") {
    *params = Ideal();
  } else if (name == "lab") {
    *params = Lab();
  } else if (name == "lab_v1") {
    *params = LabV1();
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

}  // namespace dream::world
