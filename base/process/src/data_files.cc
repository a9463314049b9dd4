#include "dream/process/data_files.h"

#include <filesystem>

#include "dream/process/process_group.h"

#if !defined(DREAM_BUILD_DIR) || !defined(DREAM_BIN_TO_DATA) || !defined(DREAM_BUILD_TYPES_JAR) ||                 \
    !defined(DREAM_BRIDGE_PYTHON_DIR) || !defined(DREAM_PYTHON_RUNTIME_DIR) || !defined(DREAM_PYTHON_TYPES_DIR) || \
    !defined(DREAM_PYTHON_HOST_MODULE) || !defined(DREAM_BIN_TO_LIB)
#error "base/process/CMakeLists.txt defines where the build tree and the installed data files are"
#endif

namespace dream::process {

namespace fs = std::filesystem;

bool DataFiles::RunningFromBuildTree() {
  std::error_code error;
  return fs::equivalent(fs::path(SelfExecutable()).parent_path(), DREAM_BUILD_DIR, error);
}

std::string DataFiles::Locate(const std::string& installed_relative_path, const std::string& build_tree_path) {
  if (RunningFromBuildTree()) return build_tree_path;
  return (fs::path(SelfExecutable()).parent_path() / DREAM_BIN_TO_DATA / installed_relative_path)
      .lexically_normal()
      .string();
}

std::string DataFiles::TypesJar() { return Locate("java/dream_lcmtypes.jar", DREAM_BUILD_TYPES_JAR); }

std::string DataFiles::BridgePythonDir() { return Locate("bridge", DREAM_BRIDGE_PYTHON_DIR); }

std::string DataFiles::PythonRuntimeDir() { return Locate("python-runtime", DREAM_PYTHON_RUNTIME_DIR); }

std::string DataFiles::PythonTypesDir() { return Locate("python", DREAM_PYTHON_TYPES_DIR); }

std::string DataFiles::PythonHostModule() {
  if (RunningFromBuildTree()) return DREAM_PYTHON_HOST_MODULE;
  return (fs::path(SelfExecutable()).parent_path() / DREAM_BIN_TO_LIB / "libdream_python_embedded.so")
      .lexically_normal()
      .string();
}

std::string DataFiles::AgentBinary() { return (fs::path(SelfExecutable()).parent_path() / "dream-agent").string(); }

std::string DataFiles::SharedAgentBinary() {
  return (fs::path(SelfExecutable()).parent_path() / "dream-agent-shared").string();
}

}  // namespace dream::process
