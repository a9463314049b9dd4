#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/python_embedded/python_agent_host.h"
#include "dream/config/controller_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/python_host/python_host_process.h"

namespace dream::hosting {

/// The agents of some robots of a run, on a bus of this process, whatever
/// language their controller is in: kinds whose robots run in C++ in an
/// agent_host::AgentHost, kinds whose robots run in the Python runtime
/// (ControllerKind::runtime, as `python` does) in a PythonHostProcess (a
/// process of their own, relayed to this bus). Every command that hosts agents
/// (run, agent, lab-replay) goes through here.
class HostedAgents {
 public:
  /// Checks the controller section as far as can be done before a run: the
  /// kind and its keys, and for a kind of the Python runtime its module,
  /// class and own keys (in a process of its own, as the run's). `built`: the run's factory
  /// when the caller built it already (a
  /// RunSession does), so the config's plugins are not loaded again.
  /// @throws config::ConfigError naming file, line and key.
  /// `start_timeout_s`: the run's world.start_timeout_s (0: the default),
  /// which bounds loading the module and each robot's setup().
  /// `stop` (Ctrl-C) ends a Python check early.
  static void Check(const config::ControllerConfig& config, const agent_host::ControllerFactory* built,
                    double start_timeout_s, const std::atomic<bool>& stop);

  /// Builds the agents of `robot_ids` and subscribes them on `bus`, C++
  /// agents with `factory` when given (the run's), else with a factory of
  /// their own. `python_limits`: the run's world.agent_timeout_s and
  /// start_timeout_s (overrides included; 0: the defaults), which bound a
  /// Python controller's step and its setup(), and the idle timeout of
  /// dream agent (PythonHostProcess::Limits).
  HostedAgents(lcm::LcmBus& bus, const config::ControllerConfig& config, const std::vector<int>& robot_ids,
               const agent_host::ControllerFactory* factory = nullptr,
               const python_host::PythonHostProcess::Limits& python_limits = {});
  /// The same on a bus of their own, opened on `lcm_url` (empty:
  /// $LCM_DEFAULT_URL, else LCM's default; lcm::ResolveLcmUrl): what `dream
  /// agent` runs, whose lean program links no workflow.
  /// @throws std::invalid_argument naming a URL LCM cannot open.
  HostedAgents(const std::string& lcm_url, const config::ControllerConfig& config, const std::vector<int>& robot_ids,
               const python_host::PythonHostProcess::Limits& python_limits);
  /// The URL of the bus the agents are on.
  const std::string& url() const { return bus_.url(); }

  /// Handles `bus` until the world ends the run (true), or `stop` / silence (false).
  bool Run(const std::atomic<bool>& stop, double idle_timeout_s);
  int64_t last_step_answered() const;
  std::string end_detail() const;
  /// What the agents refused, as JSON: {"bad_messages": {channel: count},
  /// "other_runs": [run id hex], "steps_out_of_sequence": n}.
  std::string ReportJson() const;

 private:
  void Host(const config::ControllerConfig& config, const std::vector<int>& robot_ids,
            const agent_host::ControllerFactory* factory, const python_host::PythonHostProcess::Limits& python_limits);

  std::unique_ptr<lcm::LcmBus> own_bus_;  // declared first: the agents on it end before it
  lcm::LcmBus& bus_;
  std::unique_ptr<agent_host::AgentHost> cpp_;
  std::unique_ptr<python_embedded::PythonAgentHost> python_;
};

}  // namespace dream::hosting
