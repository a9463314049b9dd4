#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/lcm/lcm_bus.h"

namespace dream::python_embedded {

/// Hosts robots whose controller is a Python class (`kind: python`) on a bus
/// of this process, in an embedded Python interpreter: the Python runtime's
/// AgentHost (python/dream/agent_host.py) subscribes and publishes through
/// LCM's C library on the bus's own lcm_t, so the world and the Python agents
/// of `dream run` share one memq:// queue, and `dream agent` hosts them on
/// udpm like C++ agents. Same lockstep contract as AgentHost. Not thread
/// safe: use it from the thread that handles the bus.
///
/// The implementation is a module the tools load only when a run's
/// controller is Python (PythonHostLibrary in app/cli/), so C++ agents never map
/// libpython: hence an interface and two C entry points.
class PythonAgentHost {
 public:
  /// Where the Python runtime (the folder holding package `dream`) and
  /// lcm-gen's Python types (the folder holding their package `dream`) are.
  struct Paths {
    std::string runtime_dir;
    std::string lcmtypes_dir;
  };

  virtual ~PythonAgentHost() = default;

  /// Handles `bus` until the world reports FINISHED or ABORTED (true), or
  /// `stop` is set or no DREAM_POSES came for `idle_timeout_s` (false).
  virtual bool Run(lcm::LcmBus& bus, const std::atomic<bool>& stop, double idle_timeout_s) = 0;
  virtual bool world_finished() const = 0;
  virtual int64_t last_step_answered() const = 0;
  virtual std::string end_detail() const = 0;
  /// What the host refused, as JSON: {"bad_messages": {channel: count},
  /// "other_runs": [run id hex], "steps_out_of_sequence": n}.
  virtual std::string ReportJson() const = 0;
};

/// dream_python_host_watch: what the module's watchdog thread watches (set it
/// before the first check or create; the limits may change later). While
/// `stop` is set, a running controller call (a step, or loading and setup())
/// is interrupted: it raises dream.RunInterrupted, which ends the host's
/// handling of the step without blaming the controller. A step's call still
/// running after 0.8 x the world's `agent_timeout_s` (0: no limit), or loading
/// the module and setup() after 0.8 x its `start_timeout_s` (0: no limit),
/// raises dream.ControllerTimeout: that robot's controller failed
/// (DREAM_FAULT_<id>, heard before the world would give up on the silent
/// agent), the others go on. Either lands at the next Python bytecode the
/// call runs: a call blocked in C code is ended by the process that watches
/// this one (PythonHostProcess), through `cell`.
///
/// `cell`: where the Python side marks each controller call, kCallCellWords
/// int64 (a token unique to the call, > 0 for a step, < 0 for loading and
/// setup(), 0 between calls; the robot id; the step), so that a process
/// sharing the memory can time the call too; then the token of the latest
/// call the watchdog raised ControllerTimeout in (word kCallCellRaised, the
/// watchdog's), so that process kills only after the raise had its chance;
/// nullptr: the module's own.
inline constexpr int kCallCellWords = 4;
inline constexpr int kCallCellRaised = 3;
using PythonHostWatchFunction = void (*)(const std::atomic<bool>* stop, double agent_timeout_s, double start_timeout_s,
                                         std::atomic<int64_t>* cell);
inline constexpr const char* kPythonHostWatchSymbol = "dream_python_host_watch";

/// dream_python_host_check: loads the controller's module and class and
/// checks its own keys against the class's KEYS, without touching a bus.
/// @throws config::ConfigError naming file, line and key (or the module's own
///         error with its file and line); std::runtime_error when the Python
///         runtime cannot start.
using PythonHostCheckFunction = void (*)(const std::string& spec_json, const PythonAgentHost::Paths& paths);
inline constexpr const char* kPythonHostCheckSymbol = "dream_python_host_check";

/// dream_python_host_create: the agents of `robot_ids` built from `spec_json`
/// (the python kind's ControllerKind::runtime_spec), subscribed on `bus`. @throws as the check.
using PythonHostCreateFunction = std::unique_ptr<PythonAgentHost> (*)(lcm::LcmBus& bus, const std::string& spec_json,
                                                                      const std::vector<int>& robot_ids,
                                                                      int64_t agent_id,
                                                                      const PythonAgentHost::Paths& paths);
inline constexpr const char* kPythonHostCreateSymbol = "dream_python_host_create";

}  // namespace dream::python_embedded
