#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dream/kind_api/experiment_builder.h"
#include "dream/config/config_node.h"

namespace dream::python {

/// The `python` kind: robots whose controller is a Python class,
///
///     controller: {kind: python, module: python/my_robot.py, class: MyRobot, ...its own keys}
///
/// They run in the Python runtime (python/dream/), hosted on the bus by
/// dream::python_host or inside a Robotarium submission, never as C++ Robots:
/// this builder checks `module` and `class`, gives the kind its default parts
/// (AgentPartsConfig::Defaults) and the common safety metrics, and leaves the
/// class's own keys to the Python side, which checks them against the class's
/// KEYS with the lines PythonControllerSpecJson() hands it.
class PythonControllerBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "python";
  static std::vector<const char*> Keys() { return {"module", "class"}; }

  /// @throws config::ConfigError when `module` is not a readable .py file
  ///         (relative paths are taken from the config file's folder) or
  ///         `class` is not a Python identifier.
  PythonControllerBuilder(const config::ConfigNode& section, int num_robots);

  /// Always throws std::logic_error: Python robots are not C++ Robots.
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;

  /// Absolute path of the controller's module file.
  const std::string& module_path() const { return module_path_; }
  const std::string& class_name() const { return class_name_; }
  /// The config's own spelling of `module` (relative to the config's folder, or absolute).
  const std::string& module_as_written() const { return module_as_written_; }

 private:
  std::string module_path_;
  std::string module_as_written_;
  std::string class_name_;
};

}  // namespace dream::python
