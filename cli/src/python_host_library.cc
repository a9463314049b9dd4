#include "python_host_library.h"

#include <dlfcn.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "commands.h"
#include "data_files.h"
#include "dream/config/config_node.h"
#include "dream/config/sim_node_options.h"

namespace dream::cli {

const PythonHostLibrary& PythonHostLibrary::Get() {
  static const PythonHostLibrary library = [] {
    const std::string path = DataFiles::PythonHostModule();
    // RTLD_GLOBAL: libpython's symbols must be visible to the Python
    // extension modules the interpreter loads later (numpy's), which Debian
    // builds without a link to libpython.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      const char* error = ::dlerror();
      throw std::runtime_error("cannot load the Python agent host " + path + " (" +
                               (error != nullptr ? error : "unknown error") +
                               "); Python controllers need Debian's libpython3.11 (apt-get install libpython3-dev)");
    }
    auto watch = reinterpret_cast<agents::PythonHostWatchFunction>(::dlsym(handle, agents::kPythonHostWatchSymbol));
    auto check = reinterpret_cast<agents::PythonHostCheckFunction>(::dlsym(handle, agents::kPythonHostCheckSymbol));
    auto create =
        reinterpret_cast<agents::PythonHostCreateFunction>(::dlsym(handle, agents::kPythonHostCreateSymbol));
    if (watch == nullptr || check == nullptr || create == nullptr) {
      throw std::runtime_error(path + " is not the Python agent host of this dream (rebuild or reinstall dream)");
    }
    // A controller call blocked in Python ends with Ctrl-C / SIGTERM, and
    // one longer than a world waits for an agent fails its robot.
    watch(&StopFlag(), sim::SimNodeOptions{}.agent_timeout_s);
    return PythonHostLibrary(watch, check, create);
  }();
  return library;
}

void PythonHostLibrary::SetAgentTimeout(double agent_timeout_s) const {
  watch_(&StopFlag(), agent_timeout_s);
  agent_timeout_set_ = true;
}

namespace {

// world.agent_timeout_s of the config file `spec_json` names, when it has a
// valid one: what the world of a run from that file waits for an agent.
std::optional<double> AgentTimeoutOfConfigFile(const std::string& spec_json) {
  try {
    const nlohmann::json spec = nlohmann::json::parse(spec_json);
    const config::ConfigNode root = config::ConfigNode::LoadFile(spec.at("config_file").get<std::string>());
    const config::ConfigNode world = root.Optional("world");
    if (!world.IsDefined() || !world.IsMap() || !world.Has("agent_timeout_s")) return std::nullopt;
    const double seconds = world.Required("agent_timeout_s").AsDouble();
    if (std::isfinite(seconds) && seconds > 0) return seconds;
  } catch (const std::exception&) {
    // The run checked its config already; a file that changed since keeps the default.
  }
  return std::nullopt;
}

}  // namespace

std::unique_ptr<agents::PythonAgentHost> PythonHostLibrary::Create(lcm::LcmBus& bus, const std::string& spec_json,
                                                                   const std::vector<int>& robot_ids,
                                                                   int64_t agent_id,
                                                                   const agents::PythonAgentHost::Paths& paths) const {
  if (!agent_timeout_set_) {
    watch_(&StopFlag(), AgentTimeoutOfConfigFile(spec_json).value_or(sim::SimNodeOptions{}.agent_timeout_s));
  }
  return create_(bus, spec_json, robot_ids, agent_id, paths);
}

}  // namespace dream::cli
