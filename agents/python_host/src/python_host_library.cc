#include "dream/python_host/python_host_library.h"

#include <dlfcn.h>

#include <stdexcept>

#include "dream/config/sim_node_options.h"
#include "dream/process/data_files.h"

namespace dream::python_host {

const PythonHostLibrary& PythonHostLibrary::Get(const std::atomic<bool>& stop) {
  static const PythonHostLibrary library = [&stop] {
    const std::string path = process::DataFiles::PythonHostModule();
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
    using namespace python_embedded;  // the module's interface: its function types and symbol names
    auto watch = reinterpret_cast<PythonHostWatchFunction>(::dlsym(handle, kPythonHostWatchSymbol));
    auto check = reinterpret_cast<PythonHostCheckFunction>(::dlsym(handle, kPythonHostCheckSymbol));
    auto create = reinterpret_cast<PythonHostCreateFunction>(::dlsym(handle, kPythonHostCreateSymbol));
    if (watch == nullptr || check == nullptr || create == nullptr) {
      throw std::runtime_error(path + " is not the Python agent host of this dream (rebuild or reinstall dream)");
    }
    // A controller call blocked in Python ends with Ctrl-C / SIGTERM, and
    // one longer than a world waits for an agent fails its robot.
    const config::SimNodeOptions defaults;
    watch(&stop, defaults.agent_timeout_s, defaults.start_timeout_s, nullptr);
    return PythonHostLibrary(watch, check, create, &stop);
  }();
  return library;
}

void PythonHostLibrary::Watch(double agent_timeout_s, double start_timeout_s, std::atomic<int64_t>* cell) const {
  const config::SimNodeOptions defaults;
  watch_(stop_, agent_timeout_s > 0 ? agent_timeout_s : defaults.agent_timeout_s,
         start_timeout_s > 0 ? start_timeout_s : defaults.start_timeout_s, cell);
}

std::unique_ptr<python_embedded::PythonAgentHost> PythonHostLibrary::Create(
    lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids, int64_t agent_id,
    const python_embedded::PythonAgentHost::Paths& paths) const {
  return create_(bus, spec_json, robot_ids, agent_id, paths);
}

}  // namespace dream::python_host
