#pragma once

#include "dream/kind_api/controller_kind.h"

namespace dream::go_to_goal {

/// The `go_to_goal` kind as the agent host registers it among the built-in kinds
/// (agents/kinds/CMakeLists.txt lists it).
kind_api::ControllerKind Kind();

}  // namespace dream::go_to_goal
