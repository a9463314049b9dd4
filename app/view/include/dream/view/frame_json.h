#pragma once

#include <string>

#include "dream/view/view_frame.h"
#include "dream/view/view_setup.h"

namespace dream::view {

/// The frame as the page reads it: one JSON object, {"type":"frame", ...},
/// positions in metres to 0.1 mm, angles to 1e-4 rad; a value that is not a
/// finite number (a forged message) is written as null, which the page skips.
/// "other_world" is null, or the second world on the bus the page mentions:
/// {"run": id as a decimal string, "step", "state" (null when unknown), "runs"}.
std::string FrameJson(const ViewFrame& frame);

/// What the page needs before frames: {"type":"setup", ...}: the mode, the
/// arena, the robot size, the time step, and the goals and sensor reaches of
/// the run's config when known.
std::string SetupJson(const ViewSetup& setup);

}  // namespace dream::view
