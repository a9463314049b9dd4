#include "dream/bridge/submission_params.h"

#include <cmath>
#include <stdexcept>

#include "dream/bridge/submission_format.h"

namespace dream::bridge {
namespace {

/// The barrier certificate's parameters of a format-3 file (its flag checked to be 0 or 1).
barriers::UnicycleBarrierParams BarrierParamsOf(const double* p) {
  barriers::UnicycleBarrierParams barrier;
  barrier.safety_radius_m = p[kParamBarrierSafetyRadius];
  barrier.barrier_gain = p[kParamBarrierGain];
  barrier.projection_distance_m = p[kParamBarrierProjectionDistance];
  barrier.magnitude_limit_mps = p[kParamBarrierMagnitudeLimit];
  barrier.boundary.reset();
  if (p[kParamBarrierHasBoundary] == 1.0) {
    barrier.boundary = barriers::BoundaryBox{p[kParamBarrierBoundaryXMin], p[kParamBarrierBoundaryXMax],
                                             p[kParamBarrierBoundaryYMin], p[kParamBarrierBoundaryYMax]};
  }
  return barrier;
}

}  // namespace

formats::NpyArray SubmissionParams::ToNpy() const {
  formats::NpyArray array;
  array.shape = {kParamCount};
  array.values.assign(kParamCount, 0.0);
  double* p = array.values.data();
  p[kParamMagic] = kParamsMagic;
  p[kParamFormatVersion] = kFormatVersion;
  p[kParamNumRobots] = num_robots;
  p[kParamSteps] = static_cast<double>(steps);
  p[kParamStrategy] = options.strategy == Strategy::kTrack    ? kStrategyTrack
                      : options.strategy == Strategy::kReplay ? kStrategyReplay
                                                              : kStrategyController;
  p[kParamBarriers] = options.barriers ? 1.0 : 0.0;
  p[kParamSettleMaxSteps] = options.settle_max_steps;
  p[kParamSettlePositionTolerance] = options.settle_position_tolerance_m;
  p[kParamSettleHeadingTolerance] = options.settle_heading_tolerance_rad;
  p[kParamSettleGainV] = options.settle_gain_v_per_s;
  p[kParamSettleGainW] = options.settle_gain_w_per_s;
  p[kParamGainX] = options.gain_x_per_s;
  p[kParamGainY] = options.gain_y_per_m2;
  p[kParamGainTheta] = options.gain_theta_per_s;
  p[kParamSaveEverySteps] = options.save_every_steps;
  p[kParamWheelRadius] = wheel_radius_m;
  p[kParamBaseLength] = base_length_m;
  p[kParamMaxWheelSpeed] = max_wheel_speed_radps;
  p[kParamStopWhenDone] = stop_when_done ? 1.0 : 0.0;
  p[kParamMaxAbsV] = max_abs_v_mps;
  p[kParamMaxAbsW] = max_abs_w_radps;
  const barriers::UnicycleBarrierParams& barrier = options.barrier_params;
  p[kParamBarrierSafetyRadius] = barrier.safety_radius_m;
  p[kParamBarrierGain] = barrier.barrier_gain;
  p[kParamBarrierProjectionDistance] = barrier.projection_distance_m;
  p[kParamBarrierMagnitudeLimit] = barrier.magnitude_limit_mps;
  p[kParamBarrierHasBoundary] = barrier.boundary ? 1.0 : 0.0;
  const barriers::BoundaryBox box = barrier.boundary.value_or(barriers::BoundaryBox{});
  p[kParamBarrierBoundaryXMin] = box.x_min_m;
  p[kParamBarrierBoundaryXMax] = box.x_max_m;
  p[kParamBarrierBoundaryYMin] = box.y_min_m;
  p[kParamBarrierBoundaryYMax] = box.y_max_m;
  return array;
}

SubmissionParams SubmissionParams::FromNpy(const formats::NpyArray& array, const std::string& name) {
  auto fail = [&name](const std::string& problem) { throw std::runtime_error(name + ": " + problem); };
  const bool format1 = array.shape == std::vector<int64_t>{kParamCountFormat1};
  const bool format2 = array.shape == std::vector<int64_t>{kParamCountFormat2};
  if (array.shape != std::vector<int64_t>{kParamCount} && !format1 && !format2) {
    fail("expected " + std::to_string(kParamCount) + " numbers (a dream_params.npy of this dream version)");
  }
  const double* p = array.values.data();
  const int count = format1 ? kParamCountFormat1 : format2 ? kParamCountFormat2 : kParamCount;
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(p[i])) fail("value " + std::to_string(i) + " is not finite");
  }
  if (p[kParamMagic] != kParamsMagic) fail("is not a dream_params.npy (wrong magic number)");
  const double version = format1 ? 1.0 : format2 ? 2.0 : kFormatVersion;
  if (p[kParamFormatVersion] != version) {
    fail("has format version " + std::to_string(p[kParamFormatVersion]) + " with " + std::to_string(count) +
         " numbers; this dream reads version 1 (18 numbers), 2 (21) and " + std::to_string(kFormatVersion) + " (" +
         std::to_string(kParamCount) + "); export the run again");
  }
  auto whole = [&](int index, double low, double high, const char* what) {
    const double value = p[index];
    if (value != std::floor(value) || value < low || value > high) {
      fail(std::string(what) + " = " + std::to_string(value) + " is not a whole number in [" + std::to_string(low) +
           ", " + std::to_string(high) + "]");
    }
    return static_cast<int64_t>(value);
  };
  SubmissionParams params;
  params.num_robots = static_cast<int>(whole(kParamNumRobots, 1, 50, "number of robots"));
  params.steps = whole(kParamSteps, 1, 1e8, "steps");
  const double strategy = p[kParamStrategy];
  if (strategy == kStrategyTrack) {
    params.options.strategy = Strategy::kTrack;
  } else if (strategy == kStrategyReplay) {
    params.options.strategy = Strategy::kReplay;
  } else if (strategy == kStrategyController && !format1) {
    params.options.strategy = Strategy::kController;
  } else {
    fail("unknown strategy " + std::to_string(strategy));
  }
  params.options.barriers = whole(kParamBarriers, 0, 1, "barriers") == 1;
  params.options.settle_max_steps = static_cast<int>(whole(kParamSettleMaxSteps, 0, 3000, "settle steps"));
  params.options.settle_position_tolerance_m = p[kParamSettlePositionTolerance];
  params.options.settle_heading_tolerance_rad = p[kParamSettleHeadingTolerance];
  params.options.settle_gain_v_per_s = p[kParamSettleGainV];
  params.options.settle_gain_w_per_s = p[kParamSettleGainW];
  params.options.gain_x_per_s = p[kParamGainX];
  params.options.gain_y_per_m2 = p[kParamGainY];
  params.options.gain_theta_per_s = p[kParamGainTheta];
  params.options.save_every_steps = static_cast<int>(whole(kParamSaveEverySteps, 1, 1e8, "save interval"));
  params.wheel_radius_m = p[kParamWheelRadius];
  params.base_length_m = p[kParamBaseLength];
  params.max_wheel_speed_radps = p[kParamMaxWheelSpeed];
  params.stop_when_done = !format1 && whole(kParamStopWhenDone, 0, 1, "stop when done") == 1;
  if (!format1) {
    params.max_abs_v_mps = p[kParamMaxAbsV];
    params.max_abs_w_radps = p[kParamMaxAbsW];
    if (params.options.strategy == Strategy::kController && !(params.max_abs_v_mps > 0 && params.max_abs_w_radps > 0)) {
      fail("the command limits must be positive for the controller strategy");
    }
  }
  if (!format1 && !format2) {
    whole(kParamBarrierHasBoundary, 0, 1, "barrier boundary");
    params.options.barrier_params = BarrierParamsOf(p);
  }
  std::string error;
  if (!params.options.barrier_params.IsValid(&error)) fail("barriers: " + error);
  if (!params.options.IsValid(&error)) fail(error);
  if (!(params.wheel_radius_m > 0 && params.base_length_m > 0 && params.max_wheel_speed_radps > 0)) {
    fail("robot constants must be positive");
  }
  return params;
}

}  // namespace dream::bridge
