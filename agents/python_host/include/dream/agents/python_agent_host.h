#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/lcm/lcm_bus.h"

struct _object;  // CPython's PyObject

namespace dream::agents {

/// Hosts robots whose controller is a Python class (`kind: python`) on a bus
/// of this process, in an embedded Python interpreter: the Python runtime's
/// AgentHost (python/dream/agent_host.py) subscribes and publishes through
/// LCM's C library on the bus's own lcm_t, so the world and the Python agents
/// of `dream run` share one memq:// queue, and `dream agent` hosts them on
/// udpm like C++ agents. Same lockstep contract as AgentHost. Not thread
/// safe: use it from the thread that handles the bus.
class PythonAgentHost {
 public:
  /// Where the Python runtime (the folder holding package `dream`) and
  /// lcm-gen's Python types (the folder holding their package `dream`) are.
  struct Paths {
    std::string runtime_dir;
    std::string lcmtypes_dir;
  };

  /// Loads the controller's module and class and checks its own keys
  /// against the class's KEYS, without touching a bus.
  /// @throws config::ConfigError naming file, line and key (or the module's
  ///         own error with its file and line); std::runtime_error when the
  ///         Python runtime cannot start.
  static void Check(const std::string& spec_json, const Paths& paths);

  /// Builds the agents of `robot_ids` from `spec_json` (PythonControllerSpecJson)
  /// and subscribes them on `bus`. @throws as Check().
  PythonAgentHost(lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids,
                  int64_t agent_id, const Paths& paths);
  ~PythonAgentHost();
  PythonAgentHost(const PythonAgentHost&) = delete;
  PythonAgentHost& operator=(const PythonAgentHost&) = delete;

  /// Handles `bus` until the world reports FINISHED or ABORTED (true), or
  /// `stop` is set or no DREAM_POSES came for `idle_timeout_s` (false).
  bool Run(lcm::LcmBus& bus, const std::atomic<bool>& stop, double idle_timeout_s);

  bool world_finished() const;
  int64_t last_step_answered() const;
  std::string end_detail() const;
  /// Robots whose controller failed, "robot <id>: <FILE:LINE: ...>" each.
  std::vector<std::string> faults() const;

 private:
  _object* host_ = nullptr;
};

}  // namespace dream::agents
