#pragma once

#include <vector>

#include "calibration_series.h"
#include "dream/calibration/calibration_report.h"
#include "dream/world/unicycle_command.h"

namespace dream::calibration {

// The tracker's and the loop's keys, read from poses and times directly:
// noise at rest and moving, rounding, repeated poses, step timing. `moving`
// holds, per series and step, whether the robot was moving at that
// measurement (from the fitted dynamics), as the world decides it.
class CalibrationTracker {
 public:
  CalibrationTracker(const std::vector<CalibrationSeries>& series, const std::vector<std::vector<bool>>& moving,
                     const world::RealismParams& base);

  // Noise at rest from consecutive measurements of resting robots; needs no
  // dynamics, so the dynamics fit can weigh its residuals with it.
  static void RestNoise(const std::vector<CalibrationSeries>& series, double* position_sigma_m,
                        double* heading_sigma_rad);

  // Appends the keys it fits (or keeps) to report->keys and the evidence to
  // the report's histograms; sets report->params.
  void Fit(CalibrationReport* report) const;

 private:
  void FitNoise(CalibrationReport* report) const;
  void FitQuanta(CalibrationReport* report) const;
  void FitDropouts(CalibrationReport* report) const;
  void FitTiming(CalibrationReport* report) const;

  const std::vector<CalibrationSeries>& series_;
  const std::vector<std::vector<bool>>& moving_;
  world::RealismParams base_;
};

// Helpers shared by the fits.
FittedKey KeptKey(const world::RealismParams& base, const char* key, const std::string& why);
double RealismValue(const world::RealismParams& params, const std::string& key);
void SetRealismValue(world::RealismParams* params, const std::string& key, double value);
void AddKey(CalibrationReport* report, FittedKey key);

}  // namespace dream::calibration
