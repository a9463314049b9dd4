#pragma once

#include <string_view>

#include "dream/view/view_frame.h"
#include "dream/view/view_setup.h"
#include "dream/view/violation_mark.h"
#include "json_writer.h"

namespace dream::view {

/// Parts the frame, the setup and the replay write alike (frame_json.cc).
void AppendViolation(JsonWriter& json, const ViolationMark& mark);
/// `key`: a run's status as the page reads it (live frames' "status", the
/// replay's "final"), or null when none was seen.
void WriteStatusJson(JsonWriter& json, std::string_view key, const ViewFrame::Status& status);
/// The setup's fields (mode, arena, robot size, goals, sensor reaches) inside an open object.
void AppendSetupFields(JsonWriter& json, const ViewSetup& setup);

}  // namespace dream::view
