#pragma once

// The controller plugin API: a shared library (a CMake MODULE linking
// dream::agent_host) that adds experiment kinds to the dream tools. A config
// names it under `plugins:`; `dream run`, `dream agent`, `dream launch` and
// every other tool that reads the config load it before building agents.
//
//     #include "dream/agent_host/controller_plugin.h"
//     DREAM_REGISTER_ROBOT("orbit", OrbitRobot, {"radius_m", "speed_mps"})  // one Robot subclass
//
//     DREAM_REGISTER_CONTROLLER(OrbitBuilder)   // one ExperimentBuilder (own metrics)
//
//     DREAM_CONTROLLER_PLUGIN(registry) {       // several kinds, or by hand
//       registry->Add(dream::kind_api::ControllerKind::Of<OrbitBuilder>());
//       registry->Add(dream::kind_api::ControllerKind::OfRobot<SpiralRobot>("spiral", {"pitch_m"}));
//     }
//
// See docs/writing-a-controller.md and docs/examples/out_of_tree_controller/.

#include "dream/kind_api/controller_kind.h"
#include "dream/agent_host/controller_registry.h"

/// Bumped whenever a change to the classes a plugin builds on (Robot,
/// ExperimentBuilder, ExperimentMetrics, ControllerKind, ControllerRegistry,
/// the parts) breaks plugins compiled against an older version. The tools
/// refuse a plugin built for another version. 2: a builder may return no
/// experiment metrics (MakeMetrics() default), which a version-1 tool would
/// not expect. 3: the kind API (ExperimentBuilder, ControllerKind, the parts,
/// FieldReader, RobotClassBuilder) moved to dream::kind_api.
#define DREAM_PLUGIN_API_VERSION 3

/// Keeps a plugin's entry points visible under -fvisibility=hidden.
#define DREAM_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

namespace dream::agent_host {

/// The symbols the tools look up in a plugin (with dlsym).
inline constexpr const char* kPluginApiVersionSymbol = "dream_plugin_api_version";
inline constexpr const char* kRegisterControllersSymbol = "dream_register_controllers";

/// Their signatures.
using PluginApiVersionFunction = int (*)();
using RegisterControllersFunction = void (*)(ControllerRegistry* registry);

}  // namespace dream::agent_host

/// Defines a plugin's two entry points; the braces that follow are the body
/// of the registration function, with `registry` (a ControllerRegistry*) to
/// Add() kinds to.
#define DREAM_CONTROLLER_PLUGIN(registry)                                                 \
  DREAM_PLUGIN_EXPORT int dream_plugin_api_version() { return DREAM_PLUGIN_API_VERSION; } \
  DREAM_PLUGIN_EXPORT void dream_register_controllers(::dream::agent_host::ControllerRegistry* registry)

/// A whole plugin with one kind, described by its ExperimentBuilder (see
/// ControllerKind::Of for the static members it needs).
#define DREAM_REGISTER_CONTROLLER(Builder)                                         \
  DREAM_CONTROLLER_PLUGIN(dream_plugin_registry_) {                                \
    dream_plugin_registry_->Add(::dream::kind_api::ControllerKind::Of<Builder>()); \
  }

/// A whole plugin with one kind that is one Robot subclass: the kind's name,
/// the class, and the robot's own keys of the `controller:` section as a
/// braced list (`{}` for none). See ControllerKind::OfRobot and
/// RobotClassBuilder for the constructor the class needs.
///     DREAM_REGISTER_ROBOT("orbit", OrbitRobot, {"radius_m", "speed_mps"})
/// (Variadic only because the preprocessor splits the braced list at its commas.)
#define DREAM_REGISTER_ROBOT(kind_name, RobotClass, ...)                                                          \
  DREAM_CONTROLLER_PLUGIN(dream_plugin_registry_) {                                                               \
    dream_plugin_registry_->Add(                                                                                  \
        ::dream::kind_api::ControllerKind::OfRobot<RobotClass>(kind_name, std::vector<std::string> __VA_ARGS__)); \
  }
