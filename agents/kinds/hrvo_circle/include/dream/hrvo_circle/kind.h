#pragma once

#include "dream/kind_api/controller_kind.h"

namespace dream::hrvo_circle {

/// The `hrvo_circle` kind as the agent host registers it among the built-in kinds
/// (agents/kinds/CMakeLists.txt lists it).
kind_api::ControllerKind Kind();

}  // namespace dream::hrvo_circle
