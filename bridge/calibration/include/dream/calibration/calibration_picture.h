#pragma once

#include <string>

#include <vector>

#include "dream/calibration/calibration_report.h"
#include "dream/calibration/lab_model_check.h"
#include "dream/render/render_format.h"

namespace dream::calibration {

/// dream calibrate's picture: real against fitted steps from rest per speed,
/// turning (commanded against measured rate, with the fitted gain), the
/// position noise at rest and moving with the fitted Gaussians, and the
/// lengths of runs of repeated poses with the fitted burst model.
/// @throws std::runtime_error naming the path when it cannot be written.
void RenderCalibrationPicture(const CalibrationReport& report, const std::string& path, render::RenderFormat format);

/// dream calibrate --check's picture: each model's 1 s position error with
/// its 95 % interval, then per model the runs' steps from rest, real (solid)
/// against the model (dashed). @throws std::runtime_error naming the path.
void RenderModelCheckPicture(const std::vector<ModelPrediction>& predictions, const std::string& path,
                             render::RenderFormat format);

}  // namespace dream::calibration
