#include "dream/hosting/hosted_agents.h"

#include <nlohmann/json.hpp>
#include <random>

#include "dream/lcm/lcm_url.h"
#include "dream/lcm/run_id.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/kind_api/controller_kind.h"

namespace dream::hosting {
namespace {

// A random identifier for this host's agents (velocity_command_t.agent_id).
int64_t NewAgentId() {
  std::random_device device;
  return static_cast<int64_t>((static_cast<uint64_t>(device()) << 32) | device()) & INT64_MAX;
}

bool RunsInPython(const agent_host::ControllerFactory& factory) {
  return factory.registered_kind().runtime == kind_api::ControllerKind::Runtime::kPython;
}

}  // namespace

void HostedAgents::Check(const config::ControllerConfig& config, const agent_host::ControllerFactory* built,
                         double start_timeout_s, const std::atomic<bool>& stop) {
  std::unique_ptr<agent_host::ControllerFactory> own;
  if (built == nullptr) {
    own = std::make_unique<agent_host::ControllerFactory>(config);  // its constructor checks the section
    built = own.get();
  }
  if (RunsInPython(*built)) {
    python_host::PythonHostProcess::Check(built->registered_kind().runtime_spec(config), start_timeout_s, stop);
  }
}

HostedAgents::HostedAgents(lcm::LcmBus& bus, const config::ControllerConfig& config, const std::vector<int>& robot_ids,
                           const agent_host::ControllerFactory* factory,
                           const python_host::PythonHostProcess::Limits& python_limits)
    : bus_(bus) {
  Host(config, robot_ids, factory, python_limits);
}

HostedAgents::HostedAgents(const std::string& lcm_url, const config::ControllerConfig& config,
                           const std::vector<int>& robot_ids,
                           const python_host::PythonHostProcess::Limits& python_limits)
    : own_bus_(std::make_unique<lcm::LcmBus>(lcm::ResolveLcmUrl(lcm_url))), bus_(*own_bus_) {
  Host(config, robot_ids, nullptr, python_limits);
}

void HostedAgents::Host(const config::ControllerConfig& config, const std::vector<int>& robot_ids,
                        const agent_host::ControllerFactory* factory,
                        const python_host::PythonHostProcess::Limits& python_limits) {
  std::unique_ptr<agent_host::ControllerFactory> own;
  if (factory == nullptr) {
    own = std::make_unique<agent_host::ControllerFactory>(config);
    factory = own.get();
  }
  if (RunsInPython(*factory)) {
    python_ = std::make_unique<python_host::PythonHostProcess>(bus_, factory->registered_kind().runtime_spec(config),
                                                               robot_ids, NewAgentId(), python_limits);
    return;
  }
  std::vector<std::unique_ptr<agents::RobotAgent>> robots;
  for (int id : robot_ids) robots.push_back(factory->Make(id));
  cpp_ = std::make_unique<agent_host::AgentHost>(bus_, std::move(robots), NewAgentId());
  cpp_->ExpectWorldOfRobots(config.num_robots);
}

bool HostedAgents::Run(const std::atomic<bool>& stop, double idle_timeout_s) {
  return python_ ? python_->Run(bus_, stop, idle_timeout_s) : cpp_->Run(stop, idle_timeout_s);
}

int64_t HostedAgents::last_step_answered() const {
  return python_ ? python_->last_step_answered() : cpp_->last_step_answered();
}

std::string HostedAgents::ReportJson() const {
  if (python_) return python_->ReportJson();
  nlohmann::ordered_json report;
  report["bad_messages"] = cpp_->bad_messages().per_channel();
  nlohmann::ordered_json first = nlohmann::ordered_json::object();
  for (const auto& [channel, bad] : cpp_->bad_messages().first()) {
    first[channel] = (bad.step >= 0 ? "step " + std::to_string(bad.step) + ": " : "") + bad.reason;
  }
  report["bad_message_first"] = first;
  nlohmann::json other_runs = nlohmann::json::array();
  for (int64_t run_id : cpp_->follower().other_runs()) other_runs.push_back(lcm::RunIdText(run_id));
  report["other_runs"] = other_runs;
  report["steps_out_of_sequence"] = cpp_->follower().steps_out_of_sequence();
  return report.dump();
}

std::string HostedAgents::end_detail() const { return python_ ? python_->end_detail() : cpp_->end_detail(); }

}  // namespace dream::hosting
