#pragma once

#include <vector>

#include "calibration_dynamics.h"
#include "calibration_series.h"
#include "dream/calibration/calibration_report.h"

namespace dream::calibration {

// The evidence the report and picture show: steps in v from rest, real
// against fitted (the effective delay and first motion per speed), and
// steady turning, commanded against measured.
void FillCalibrationEvidence(const std::vector<CalibrationSeries>& series, const CalibrationDynamics& dynamics,
                             const DynamicsParams& params, const DynamicsEvaluation& fitted, CalibrationReport* report);

// How many starts from rest (a steady command in v held 1.5 s after 20
// steps at rest) the runs hold at or below `max_speed_mps`, and at how many
// speeds (to the centimetre per second) in all.
int StartsFromRestAtOrBelow(const std::vector<CalibrationSeries>& series, double max_speed_mps, int* speeds);

// Where the line fitted to the last half of `distance_m` (sampled at
// `time_s`, from the command's step) crosses 0: the effective delay.
double EffectiveDelay(const std::vector<double>& distance_m, const std::vector<double>& time_s);

}  // namespace dream::calibration
