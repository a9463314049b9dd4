#pragma once

#include "dream/agents/framework/drawing.h"
#include "dream/drawing_t.hpp"

namespace dream::agent_host {

/// A robot's Drawing as the drawing_t its agent sends on DREAM_DRAW_<id>
/// (the header fields utime, step, run_id, robot_id and agent_id left for
/// the caller). The Drawing's bounds are drawing_t's (checked at compile
/// time), so the message is within them.
drawing_t DrawingMessageOf(const agents::Drawing& drawing);

}  // namespace dream::agent_host
