#pragma once

#include <array>
#include <string>
#include <vector>

#include "dream/world/realism_params.h"

namespace dream::calibration {

/// One world.realism key as `dream calibrate` fitted it, or why it could not.
struct FittedKey {
  std::string key;
  double value = 0.0;
  double low = 0.0;  ///< 95 % confidence interval (low == high == value when exact)
  double high = 0.0;
  bool determined = false;  ///< false: the data cannot tell; value is the base preset's
  std::string support;      ///< how much data supported it, or why it is kept
};

/// What a step in v from rest looks like, real and fitted, at one speed.
struct StepResponseCurve {
  double speed_mps = 0.0;      ///< the commanded speed of the events averaged
  int events = 0;              ///< steps from rest seen at this speed
  std::vector<double> time_s;  ///< since the command's step
  std::vector<double> real_m;  ///< mean distance driven, measured
  std::vector<double> fitted_m;
  double real_delay_s = 0.0;  ///< where the steady line s = v (t - t0) crosses 0
  double fitted_delay_s = 0.0;
  double real_first_motion_step = 0.0;  ///< mean first step with over 3 mm of motion
  double fitted_first_motion_step = 0.0;
};

/// The fit of a lab model to real runs: the realism keys with their
/// intervals, and the evidence drawn in the calibration picture.
struct CalibrationReport {
  world::RealismParams params;  ///< the base preset with every determined key fitted
  std::vector<FittedKey> keys;  ///< one per key of RealismParams::Fields(), in that order
  std::vector<std::string> sources;
  /// What the inputs needed (a time vector that is no clock, robots left
  /// out) and what the data could not pin, in words, for the report.
  std::vector<std::string> notes;
  int robots = 0;
  int64_t robot_steps = 0;

  std::vector<StepResponseCurve> step_responses;
  std::vector<std::array<double, 2>> turning;  ///< {commanded w, measured w}, a sample
  std::vector<double> rest_noise_m;            ///< per-sample position noise at rest (a sample)
  std::vector<double> moving_noise_m;          ///< the same while moving
  std::vector<int> stale_bursts;               ///< length of every run of repeated poses

  const FittedKey* Find(const std::string& key) const;
  /// The fit report: one line per key (value, interval, support), then the
  /// step responses per speed, real against fitted.
  std::string Text() const;
  /// A realism file (`world.realism: {file: ...}`): every key, fitted or
  /// kept, with the report as comments.
  std::string RealismYaml() const;
};

}  // namespace dream::calibration
