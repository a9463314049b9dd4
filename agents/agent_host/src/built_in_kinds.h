#pragma once

#include <string>

#include "dream/agent_host/controller_registry.h"

namespace dream::agent_host {

/// Adds every built-in kind to `registry`, each as `dream::<kind>::Kind()`,
/// in the order of DREAM_BUILT_IN_KINDS (agents/kinds/CMakeLists.txt), with
/// `origin`. Defined in built_in_kinds.cc, which agents/agent_host/CMakeLists.txt
/// generates from that list.
void AddBuiltInKinds(ControllerRegistry& registry, const std::string& origin);

}  // namespace dream::agent_host
