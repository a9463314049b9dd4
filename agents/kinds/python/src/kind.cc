#include "dream/python/kind.h"

#include <memory>
#include <nlohmann/json.hpp>

#include "dream/python/python_controller_builder.h"
#include "dream/python/python_controller_spec.h"
#include "dream/python/python_run_metrics.h"
#include "dream/python/python_step_metrics.h"

namespace dream::python {

kind_api::ControllerKind Kind() {
  kind_api::ControllerKind kind = kind_api::ControllerKind::Of<PythonControllerBuilder>();
  kind.checks_own_keys = true;  // the Python class declares its own keys (its KEYS)
  kind.runtime = kind_api::ControllerKind::Runtime::kPython;
  kind.runtime_spec = PythonControllerSpecJson;
  kind.file_key = "module";
  // The class's own metrics, goal and goal points live in Python: a short-lived python3 computes them.
  kind.own_metrics = [](const config::ControllerConfig& config, const kind_api::RunPoses& poses,
                        const std::string& runtime_dir) {
    return PythonRunMetrics::Compute(runtime_dir, PythonControllerSpecJson(config), poses);
  };
  // Live (the view's plots): one long-lived python3 a run, asked for the figures of the run so far.
  kind.own_step_metrics = [](const config::ControllerConfig& config, const std::string& runtime_dir) {
    return std::make_unique<PythonStepMetrics>(runtime_dir, PythonControllerSpecJson(config), config.num_robots);
  };
  kind.goals_before_run = [](const config::ControllerConfig& config, const std::string& runtime_dir) {
    return PythonRunMetrics::GoalPoints(runtime_dir, PythonControllerSpecJson(config), config.num_robots);
  };
  return kind;
}

}  // namespace dream::python
