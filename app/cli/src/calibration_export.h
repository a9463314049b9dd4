#pragma once

#include "commands.h"
#include "dream/bridge/export_options.h"

namespace dream::cli {

/// dream export --calibration --robots N: the calibration drive's config for
/// N robots, run as dream run runs a config (the ideal world, every agent in
/// this process), then exported open loop (--strategy replay: the program's
/// commands, which calibrate fits the lab's response to). A run that is not
/// clean is not exported.
int RunCalibrationExport(const ExportArgs& args, bridge::ExportOptions options);

}  // namespace dream::cli
