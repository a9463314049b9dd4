#pragma once

#include <string>
#include <vector>

#include "dream/calibration/calibration_report.h"
#include "dream/calibration/calibration_run.h"
#include "dream/world/realism_params.h"
#include "dream/files/stop_token.h"

namespace dream::calibration {

/// A lab model to hold against real runs (`dream calibrate --check`).
struct NamedModel {
  std::string name;  ///< a preset's name or a realism file's path
  world::RealismParams params;
};

/// How one model predicts real runs it may not have been fitted on.
struct ModelPrediction {
  std::string name;
  std::vector<StepResponseCurve> step_responses;  ///< the runs' starts from rest, real against this model
  double position_error_m = 0.0;                  ///< RMS error of 1 s open-loop predictions from the real poses
  double heading_error_rad = 0.0;
  /// 95 % interval of position_error_m over robots and their start points
  /// (a bootstrap over the runs' robots: one robot's predictions are not
  /// independent of each other).
  double position_error_low_m = 0.0;
  double position_error_high_m = 0.0;
  int predictions = 0;
  int robots = 0;  ///< robots the predictions came from
};

/// Holds lab models against real runs: the effective delay and first motion
/// of their starts from rest, and the error of 1 s open-loop predictions
/// (from each real pose, the model driven by the commands the run sent,
/// against the real pose 1 s later), beside what the runs themselves show
/// (a fit's statistics: gains, noise, repeated poses).
class LabModelCheck {
 public:
  /// @throws std::runtime_error as LabCalibration::Fit for unusable runs;
  ///         files::Stopped when `stop` is requested meanwhile (polled per robot).
  static std::vector<ModelPrediction> Predict(const std::vector<CalibrationRun>& runs,
                                              const std::vector<NamedModel>& models, const files::StopToken& stop = {});
  /// The side-by-side table: per speed the real and each model's effective
  /// delay and first motion; each model's prediction errors with their
  /// intervals, and a ranking only where the intervals separate; the steady
  /// turning seen against each model's; and each key the runs show (`real`,
  /// a fit of them, or why it is not pinned) against each model's value.
  static std::string Table(const CalibrationReport& real, const std::vector<ModelPrediction>& predictions,
                           const std::vector<NamedModel>& models);
  /// Which models predict better than which: "a < b" only where a's interval
  /// lies wholly below b's; the others overlap and are not ranked.
  static std::string Ranking(const std::vector<ModelPrediction>& predictions);
};

}  // namespace dream::calibration
