#include "dream/agent_host/controller_plugin_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>

#include "dream/agent_host/controller_plugin.h"
#include "dream/agent_host/controller_registry.h"

namespace dream::agent_host {
namespace {

std::mutex& LoaderMutex() {
  static std::mutex mutex;
  return mutex;
}

// A function of the dream libraries, by its linker name: the plugin must
// reach the very copy this process runs (see the check in Load).
constexpr const char* kRegistrySymbol = "_ZN5dream10agent_host18ControllerRegistry8BuiltInsEv";

std::string LastDlError() {
  const char* error = dlerror();
  return error == nullptr ? std::string("unknown error") : std::string(error);
}

}  // namespace

void ControllerPluginLoader::AddKinds(const config::ControllerConfig& config, ControllerRegistry* registry) {
  // dlopen returns the same handle for the same file, whatever path names it.
  std::set<void*> added;
  for (size_t i = 0; i < config.plugins.size(); ++i) {
    const std::string& path = config.plugins[i];
    const config::ConfigNode& entry = config.plugin_nodes.at(i);
    void* handle = nullptr;
    const Registration register_controllers = Load(path, entry, &handle);
    if (!added.insert(handle).second) continue;
    // Register into a scratch registry first, so a plugin that fails half way
    // adds nothing.
    ControllerRegistry kinds;
    try {
      register_controllers(&kinds);
      if (kinds.Names().empty()) entry.Fail(path + ": it registers no controller kind");
      registry->AddAll(kinds, path);
    } catch (const config::ConfigError&) {
      throw;
    } catch (const std::exception& e) {
      entry.Fail(path + ": " + e.what());
    }
  }
}

ControllerPluginLoader::Registration ControllerPluginLoader::Load(const std::string& path,
                                                                  const config::ConfigNode& entry, void** handle_out) {
  namespace fs = std::filesystem;
  const std::lock_guard<std::mutex> lock(LoaderMutex());
  auto fail = [&](const std::string& reason) { entry.Fail(path + ": " + reason); };
  std::error_code error;
  if (!fs::exists(path, error)) {
    fail(
        "no such file (relative plugin paths start at the config file's folder, or plugin_dir; build the plugin "
        "first)");
  }
  if (!fs::is_regular_file(path, error)) fail("not a file");
  // RTLD_NOW: a symbol the plugin needs but this dream lacks is reported
  // here, not as a crash in the middle of a run.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) fail("cannot load it: " + LastDlError());
  *handle_out = handle;

  dlerror();
  auto api_version = reinterpret_cast<PluginApiVersionFunction>(dlsym(handle, kPluginApiVersionSymbol));
  auto register_controllers = reinterpret_cast<RegisterControllersFunction>(dlsym(handle, kRegisterControllersSymbol));
  if (api_version == nullptr || register_controllers == nullptr) {
    fail(std::string("not a dream controller plugin: it has no ") +
         (api_version == nullptr ? kPluginApiVersionSymbol : kRegisterControllersSymbol) +
         "() (define it with DREAM_REGISTER_CONTROLLER or DREAM_CONTROLLER_PLUGIN from "
         "dream/agent_host/controller_plugin.h)");
  }
  // A plugin linked with another build of the dream libraries (another
  // soname, another prefix's RPATH) would bring a second copy of them:
  // classes that look alike but are not the same. Refuse it.
  void* plugins_registry = dlsym(handle, kRegistrySymbol);
  if (plugins_registry != nullptr && plugins_registry != reinterpret_cast<void*>(&ControllerRegistry::BuiltIns)) {
    Dl_info origin{};
    const bool known = dladdr(plugins_registry, &origin) != 0 && origin.dli_fname != nullptr;
    fail(std::string("it uses another copy of the dream libraries (") + (known ? origin.dli_fname : "unknown") +
         "); rebuild it against the dream that loads it");
  }
  const int version = api_version();
  if (version != DREAM_PLUGIN_API_VERSION) {
    fail("built for dream plugin API " + std::to_string(version) + ", this dream has API " +
         std::to_string(DREAM_PLUGIN_API_VERSION) + "; rebuild it against this dream's installation");
  }
  return register_controllers;
}

}  // namespace dream::agent_host
