#pragma once

#include "dream/kind_api/controller_kind.h"

namespace dream::affine_formation {

/// The `affine_formation` kind as the agent host registers it among the built-in kinds
/// (agents/kinds/CMakeLists.txt lists it).
kind_api::ControllerKind Kind();

}  // namespace dream::affine_formation
