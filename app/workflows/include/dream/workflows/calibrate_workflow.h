#pragma once

#include <atomic>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

#include "dream/calibration/calibration_run.h"

namespace dream::workflows {

/// `dream calibrate`: the lab model (world.realism) fitted to real
/// Robotarium runs and written as a realism file with its fit report and a
/// picture; or, with `check_models`, lab models held against the runs side
/// by side, nothing written but the picture asked for
/// (docs/calibration.md). Prints the report.
class CalibrateWorkflow {
 public:
  struct Options {
    std::vector<std::string> inputs;        ///< run folders, .npz, .mat or .npy files
    std::string out_path;                   ///< the realism file to write (YAML); not with check_models
    std::string picture_path;               ///< empty: the realism file's name with .png (--check: none)
    std::string base = "lab";               ///< the preset whose values the undetermined keys keep
    std::vector<std::string> check_models;  ///< presets or realism files to hold against the runs
    calibration::CalibrationInputOptions input;
    const std::atomic<bool>* stop = nullptr;  ///< the fit stops within a fraction of a second
  };

  explicit CalibrateWorkflow(std::ostream& out = std::cout) : out_(out) {}

  /// @throws std::runtime_error naming the option or file at fault;
  ///         files::Stopped when stopped (nothing written).
  void Calibrate(const Options& options) const;

 private:
  void Check(const Options& options, const std::vector<calibration::CalibrationRun>& runs) const;

  std::ostream& out_;
};

}  // namespace dream::workflows
