#pragma once

#include "dream/view/view_setup.h"
#include "dream/view/violation_mark.h"
#include "json_writer.h"

namespace dream::view {

/// Parts the frame, the setup and the replay write alike (frame_json.cc).
void AppendViolation(JsonWriter& json, const ViolationMark& mark);
/// The setup's fields (mode, arena, robot size, goals, sensor reaches) inside an open object.
void AppendSetupFields(JsonWriter& json, const ViewSetup& setup);

}  // namespace dream::view
