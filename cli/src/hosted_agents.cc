#include "hosted_agents.h"

#include "commands.h"
#include "data_files.h"
#include "dream/agents/controller_factory.h"
#include "dream/agents/python_controller_spec.h"
#include "python_host_library.h"

namespace dream::cli {
namespace {

agents::PythonAgentHost::Paths PythonPaths() { return {DataFiles::PythonRuntimeDir(), DataFiles::PythonTypesDir()}; }

}  // namespace

void HostedAgents::Check(const config::ControllerConfig& config) {
  if (agents::IsPythonController(config)) {
    PythonHostLibrary::Get().Check(agents::PythonControllerSpecJson(config), PythonPaths());
  } else {
    agents::ControllerFactory{config};
  }
}

HostedAgents::HostedAgents(lcm::LcmBus& bus, const config::ControllerConfig& config, const std::vector<int>& robot_ids)
    : bus_(bus) {
  if (agents::IsPythonController(config)) {
    python_ = PythonHostLibrary::Get().Create(bus, agents::PythonControllerSpecJson(config), robot_ids, NewAgentId(),
                                              PythonPaths());
    return;
  }
  const agents::ControllerFactory factory(config);
  std::vector<std::unique_ptr<agents::RobotAgent>> robots;
  for (int id : robot_ids) robots.push_back(factory.Make(id));
  cpp_ = std::make_unique<agents::AgentHost>(bus, std::move(robots), NewAgentId());
}

bool HostedAgents::Run(const std::atomic<bool>& stop, double idle_timeout_s) {
  return python_ ? python_->Run(bus_, stop, idle_timeout_s) : cpp_->Run(stop, idle_timeout_s);
}

int64_t HostedAgents::last_step_answered() const {
  return python_ ? python_->last_step_answered() : cpp_->last_step_answered();
}

std::string HostedAgents::end_detail() const { return python_ ? python_->end_detail() : cpp_->end_detail(); }

}  // namespace dream::cli
