#include "dream/world/realism_params.h"

#include <cmath>

#include "field_check.h"

namespace dream::sim {

using field_check::Fail;
using field_check::IsNonNegativeFinite;
using field_check::IsPositiveFinite;

RealismParams RealismParams::Ideal() { return RealismParams{}; }

const std::vector<RealismParams::Field>& RealismParams::Fields() {
  using P = RealismParams;
  static const std::vector<Field> fields = {
      {"pose_noise_m", &P::pose_noise_m, nullptr},
      {"pose_noise_rad", &P::pose_noise_rad, nullptr},
      {"pose_quantum_m", &P::pose_quantum_m, nullptr},
      {"pose_quantum_rad", &P::pose_quantum_rad, nullptr},
      {"pose_delay_steps", nullptr, &P::pose_delay_steps},
      {"tracking_dropout_probability", &P::tracking_dropout_probability, nullptr},
      {"tracking_dropout_mean_steps", &P::tracking_dropout_mean_steps, nullptr},
      {"tracker_drop_s", &P::tracker_drop_s, nullptr},
      {"command_latency_steps", nullptr, &P::command_latency_steps},
      {"command_brake_s", &P::command_brake_s, nullptr},
      {"dead_zone_v_mps", &P::dead_zone_v_mps, nullptr},
      {"dead_zone_w_radps", &P::dead_zone_w_radps, nullptr},
      {"wheel_accel_limit_radps2", &P::wheel_accel_limit_radps2, nullptr},
      {"axle_length_m", &P::axle_length_m, nullptr},
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
  if (!IsNonNegativeFinite(pose_noise_m)) return Fail(error, "pose_noise_m", pose_noise_m, ">= 0 m, finite");
  if (!IsNonNegativeFinite(pose_noise_rad)) return Fail(error, "pose_noise_rad", pose_noise_rad, ">= 0 rad, finite");
  if (!IsNonNegativeFinite(pose_quantum_m)) {
    return Fail(error, "pose_quantum_m", pose_quantum_m, ">= 0 m, finite (0: not rounded)");
  }
  if (!IsNonNegativeFinite(pose_quantum_rad)) {
    return Fail(error, "pose_quantum_rad", pose_quantum_rad, ">= 0 rad, finite (0: not rounded)");
  }
  const std::string steps = "0.." + std::to_string(kMaxDelaySteps) + " steps";
  if (pose_delay_steps < 0 || pose_delay_steps > kMaxDelaySteps) {
    return Fail(error, "pose_delay_steps", pose_delay_steps, steps);
  }
  if (!(tracking_dropout_probability >= 0.0 && tracking_dropout_probability <= 1.0)) {
    return Fail(error, "tracking_dropout_probability", tracking_dropout_probability, "[0, 1]");
  }
  if (!(std::isfinite(tracking_dropout_mean_steps) && tracking_dropout_mean_steps >= 1.0)) {
    return Fail(error, "tracking_dropout_mean_steps", tracking_dropout_mean_steps,
                ">= 1 step, finite (1: each step on its own)");
  }
  if (!IsNonNegativeFinite(tracker_drop_s)) {
    return Fail(error, "tracker_drop_s", tracker_drop_s, ">= 0 s, finite (0: the tracker never drops a robot)");
  }
  if (command_latency_steps < 0 || command_latency_steps > kMaxDelaySteps) {
    return Fail(error, "command_latency_steps", command_latency_steps, steps);
  }
  if (!IsNonNegativeFinite(command_brake_s)) {
    return Fail(error, "command_brake_s", command_brake_s, ">= 0 s, finite (0: never brake)");
  }
  if (!IsNonNegativeFinite(dead_zone_v_mps)) {
    return Fail(error, "dead_zone_v_mps", dead_zone_v_mps, ">= 0 m/s, finite (0: no dead zone)");
  }
  if (!IsNonNegativeFinite(dead_zone_w_radps)) {
    return Fail(error, "dead_zone_w_radps", dead_zone_w_radps, ">= 0 rad/s, finite (0: no dead zone)");
  }
  if (!IsNonNegativeFinite(wheel_accel_limit_radps2)) {
    return Fail(error, "wheel_accel_limit_radps2", wheel_accel_limit_radps2, ">= 0 rad/s^2, finite (0: no limit)");
  }
  if (!IsPositiveFinite(axle_length_m)) return Fail(error, "axle_length_m", axle_length_m, "> 0 m, finite");
  return true;
}

bool operator==(const RealismParams& a, const RealismParams& b) {
  for (const RealismParams::Field& field : RealismParams::Fields()) {
    if (field.number != nullptr ? a.*field.number != b.*field.number : a.*field.steps != b.*field.steps) return false;
  }
  return true;
}

}  // namespace dream::sim
