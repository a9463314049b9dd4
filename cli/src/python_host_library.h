#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dream/python_host/python_agent_host.h"

namespace dream::cli {

/// The Python agent host module (agents/python_host), loaded with dlopen the
/// first time a run's controller is Python, so tools and agents with C++
/// controllers never map libpython (2.4 MB of every agent process otherwise).
class PythonHostLibrary {
 public:
  /// The module, loaded once per process.
  /// @throws std::runtime_error saying what is missing and how to get it.
  static const PythonHostLibrary& Get();

  /// The world's agent_timeout_s, for the module's watchdog
  /// (agents::PythonHostWatchFunction): a Python controller's step still
  /// running after 0.8 x this is stopped as failed. Every command that hosts
  /// agents calls this with its run's value (--set included) before Create
  /// when the config sets one; until then the watchdog uses the default
  /// (sim::SimNodeOptions). Ctrl-C and SIGTERM (StopFlag) always interrupt a
  /// running controller.
  void SetAgentTimeout(double agent_timeout_s) const;

  void Check(const std::string& spec_json, const agents::PythonAgentHost::Paths& paths) const {
    check_(spec_json, paths);
  }
  std::unique_ptr<agents::PythonAgentHost> Create(lcm::LcmBus& bus, const std::string& spec_json,
                                                  const std::vector<int>& robot_ids, int64_t agent_id,
                                                  const agents::PythonAgentHost::Paths& paths) const;

 private:
  PythonHostLibrary(agents::PythonHostWatchFunction watch, agents::PythonHostCheckFunction check,
                    agents::PythonHostCreateFunction create)
      : watch_(watch), check_(check), create_(create) {}

  agents::PythonHostWatchFunction watch_;
  agents::PythonHostCheckFunction check_;
  agents::PythonHostCreateFunction create_;
};

}  // namespace dream::cli
