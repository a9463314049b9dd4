#pragma once

#include <string>

#include "dream/bridge/calibration_report.h"
#include "dream/render/render_format.h"

namespace dream::bridge {

/// dream calibrate's picture: real against fitted steps from rest per speed,
/// turning (commanded against measured rate, with the fitted gain), the
/// position noise at rest and moving with the fitted Gaussians, and the
/// lengths of runs of repeated poses with the fitted burst model.
/// @throws std::runtime_error naming the path when it cannot be written.
void RenderCalibrationPicture(const CalibrationReport& report, const std::string& path, render::RenderFormat format);

}  // namespace dream::bridge
