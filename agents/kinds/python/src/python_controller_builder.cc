#include "dream/python/python_controller_builder.h"

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "dream/config/controller_config.h"

namespace dream::python {
namespace {

namespace fs = std::filesystem;

bool IsPythonIdentifier(const std::string& text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text[0])) != 0) return false;
  for (char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') return false;
  }
  return true;
}

}  // namespace

PythonControllerBuilder::PythonControllerBuilder(const config::ConfigNode& section, int num_robots) {
  (void)num_robots;
  const config::ConfigNode module = section.Required("module");
  module_as_written_ = module.AsString();
  // The run folder keeps a copy at the same relative path beside its
  // config.yaml, so a relative path must stay inside the config's folder.
  const fs::path path = config::FileBesideConfig(module, "module");
  // The module's base name becomes a file of its own in a Robotarium
  // submission and is imported by it, so it must be a module name.
  if (path.extension() != ".py" || !IsPythonIdentifier(path.stem().string())) {
    module.Fail("'" + module_as_written_ +
                "' is not a Python module file: expected a name like my_robot.py (letters, digits, _)");
  }
  std::error_code error;
  // access(), not an open: nothing here can wait on what the path names.
  if (!fs::is_regular_file(path, error) || ::access(path.c_str(), R_OK) != 0) {
    module.Fail("cannot read '" + path.string() + "'; relative paths are taken from the config file's folder");
  }
  module_path_ = fs::absolute(path, error).lexically_normal().string();
  const config::ConfigNode class_node = section.Required("class");
  class_name_ = class_node.AsString();
  if (!IsPythonIdentifier(class_name_)) {
    class_node.Fail("'" + class_name_ + "' is not a Python class name (letters, digits, _)");
  }
}

std::unique_ptr<agents::Robot> PythonControllerBuilder::MakeRobot(int robot_id,
                                                                  const agents::RobotParams& params) const {
  (void)params;
  throw std::logic_error("robot " + std::to_string(robot_id) + " of kind python runs in the Python runtime (" +
                         module_path_ + "), hosted by dream::python_host, not as a C++ agents::Robot");
}

}  // namespace dream::python
