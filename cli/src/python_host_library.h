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

  void Check(const std::string& spec_json, const agents::PythonAgentHost::Paths& paths) const {
    check_(spec_json, paths);
  }
  std::unique_ptr<agents::PythonAgentHost> Create(lcm::LcmBus& bus, const std::string& spec_json,
                                                  const std::vector<int>& robot_ids, int64_t agent_id,
                                                  const agents::PythonAgentHost::Paths& paths) const {
    return create_(bus, spec_json, robot_ids, agent_id, paths);
  }

 private:
  PythonHostLibrary(agents::PythonHostCheckFunction check, agents::PythonHostCreateFunction create)
      : check_(check), create_(create) {}

  agents::PythonHostCheckFunction check_;
  agents::PythonHostCreateFunction create_;
};

}  // namespace dream::cli
