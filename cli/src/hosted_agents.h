#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/python_host/python_agent_host.h"
#include "dream/config/controller_config.h"
#include "dream/lcm/lcm_bus.h"

namespace dream::cli {

/// The agents of some robots of a run, on a bus of this process, whatever
/// language their controller is in: C++ kinds in an agents::AgentHost, the
/// python kind in an agents::PythonAgentHost (embedded interpreter). Every
/// command that hosts agents (run, agent, lab-replay) goes through here.
class HostedAgents {
 public:
  /// Checks the controller section as far as can be done before a run: the
  /// kind and its keys, and for the python kind its module, class and own
  /// keys. `built`: the run's factory when the caller built it already (a
  /// RunSession does), so the config's plugins are not loaded again.
  /// @throws config::ConfigError naming file, line and key.
  static void Check(const config::ControllerConfig& config, const agents::ControllerFactory* built = nullptr);

  /// Builds the agents of `robot_ids` and subscribes them on `bus`, C++
  /// agents with `factory` when given (the run's), else with a factory of
  /// their own. `world_agent_timeout_s`: how long the run's world waits for
  /// an agent (its world.agent_timeout_s, overrides included), which bounds a
  /// Python controller's step (PythonHostLibrary::SetAgentTimeout); 0 when
  /// the caller does not know it (dream agent).
  HostedAgents(lcm::LcmBus& bus, const config::ControllerConfig& config, const std::vector<int>& robot_ids,
               const agents::ControllerFactory* factory = nullptr, double world_agent_timeout_s = 0.0);

  /// Handles `bus` until the world ends the run (true), or `stop` / silence (false).
  bool Run(const std::atomic<bool>& stop, double idle_timeout_s);
  int64_t last_step_answered() const;
  std::string end_detail() const;
  /// What the agents refused, as JSON: {"bad_messages": {channel: count},
  /// "other_runs": [run id hex], "steps_out_of_sequence": n}.
  std::string ReportJson() const;

 private:
  lcm::LcmBus& bus_;
  std::unique_ptr<agents::AgentHost> cpp_;
  std::unique_ptr<agents::PythonAgentHost> python_;
};

}  // namespace dream::cli
