#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/python_embedded/python_agent_host.h"

namespace dream::python_host {

/// The Python agent host module (agents/python_embedded), loaded with dlopen only
/// by the process that hosts Python controllers (dream-agent-shared --python-host,
/// started by PythonHostProcess), so the tools never map libpython.
class PythonHostLibrary {
 public:
  /// The module, loaded once per process; `stop` (the process's Ctrl-C and
  /// SIGTERM, as the first call gives it) interrupts a running controller.
  /// @throws std::runtime_error saying what is missing and how to get it.
  static const PythonHostLibrary& Get(const std::atomic<bool>& stop);

  /// The world's agent_timeout_s and start_timeout_s, for the module's
  /// watchdog (python_embedded::PythonHostWatchFunction): a Python controller's step
  /// still running after 0.8 x the first, or its loading and setup() after
  /// 0.8 x the second, is stopped as failed; `cell` is where the calls are
  /// marked, shared with the process that watches this one. Called before
  /// Check and Create (dream-agent-shared --python-host); until then the watchdog
  /// uses the defaults (config::SimNodeOptions). The stop given to Get()
  /// always interrupts a running controller.
  void Watch(double agent_timeout_s, double start_timeout_s, std::atomic<int64_t>* cell) const;

  void Check(const std::string& spec_json, const python_embedded::PythonAgentHost::Paths& paths) const {
    check_(spec_json, paths);
  }
  std::unique_ptr<python_embedded::PythonAgentHost> Create(lcm::LcmBus& bus, const std::string& spec_json,
                                                           const std::vector<int>& robot_ids, int64_t agent_id,
                                                           const python_embedded::PythonAgentHost::Paths& paths) const;

 private:
  PythonHostLibrary(python_embedded::PythonHostWatchFunction watch, python_embedded::PythonHostCheckFunction check,
                    python_embedded::PythonHostCreateFunction create, const std::atomic<bool>* stop)
      : watch_(watch), check_(check), create_(create), stop_(stop) {}

  python_embedded::PythonHostWatchFunction watch_;
  python_embedded::PythonHostCheckFunction check_;
  python_embedded::PythonHostCreateFunction create_;
  const std::atomic<bool>* stop_;
};

}  // namespace dream::python_host
