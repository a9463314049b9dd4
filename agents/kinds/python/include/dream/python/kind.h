#pragma once

#include "dream/kind_api/controller_kind.h"

namespace dream::python {

/// The `python` kind as the agent host registers it among the built-in kinds
/// (agents/kinds/CMakeLists.txt lists it).
kind_api::ControllerKind Kind();

}  // namespace dream::python
