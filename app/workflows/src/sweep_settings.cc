#include "dream/workflows/sweep_settings.h"

#include <stdexcept>

#include "dream/config/config_node.h"
#include "dream/workflows/script_run_workflow.h"

namespace dream::workflows {

std::string SweepSettings::BaseConfigText() const {
  if (ScriptRunWorkflow::IsScript(config_path))
    return ScriptRunWorkflow::BaseConfigText(config_path, python_runtime_dir);
  return config::ConfigNode::ReadFile(config_path);
}

SweepSettings::Engine SweepSettings::ParseEngine(const std::string& name) {
  if (name == "local") return Engine::kLocal;
  if (name == "slurm") return Engine::kSlurm;
  if (name == "plan") return Engine::kPlan;
  throw std::invalid_argument("--engine " + name + ": expected local, slurm or plan");
}

std::string SweepSettings::EngineName(Engine engine) {
  switch (engine) {
    case Engine::kSlurm:
      return "slurm";
    case Engine::kPlan:
      return "plan";
    case Engine::kLocal:
      break;
  }
  return "local";
}

}  // namespace dream::workflows
