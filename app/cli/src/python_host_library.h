#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/python_host/python_agent_host.h"

namespace dream::cli {

/// The Python agent host module (agents/python_host), loaded with dlopen only
/// by the process that hosts Python controllers (dream-agent --python-host,
/// started by PythonHostProcess), so the tools never map libpython.
class PythonHostLibrary {
 public:
  /// The module, loaded once per process.
  /// @throws std::runtime_error saying what is missing and how to get it.
  static const PythonHostLibrary& Get();

  /// The world's agent_timeout_s and start_timeout_s, for the module's
  /// watchdog (python_host::PythonHostWatchFunction): a Python controller's step
  /// still running after 0.8 x the first, or its loading and setup() after
  /// 0.8 x the second, is stopped as failed; `cell` is where the calls are
  /// marked, shared with the process that watches this one. Called before
  /// Check and Create (dream-agent --python-host); until then the watchdog
  /// uses the defaults (config::SimNodeOptions). Ctrl-C and SIGTERM (StopFlag)
  /// always interrupt a running controller.
  void Watch(double agent_timeout_s, double start_timeout_s, std::atomic<int64_t>* cell) const;

  void Check(const std::string& spec_json, const python_host::PythonAgentHost::Paths& paths) const {
    check_(spec_json, paths);
  }
  std::unique_ptr<python_host::PythonAgentHost> Create(lcm::LcmBus& bus, const std::string& spec_json,
                                                  const std::vector<int>& robot_ids, int64_t agent_id,
                                                  const python_host::PythonAgentHost::Paths& paths) const;

 private:
  PythonHostLibrary(python_host::PythonHostWatchFunction watch, python_host::PythonHostCheckFunction check,
                    python_host::PythonHostCreateFunction create)
      : watch_(watch), check_(check), create_(create) {}

  python_host::PythonHostWatchFunction watch_;
  python_host::PythonHostCheckFunction check_;
  python_host::PythonHostCreateFunction create_;
};

}  // namespace dream::cli
