#include "dream/bridge/controller_module_copy.h"

#include <filesystem>

#include "dream/agent_host/python_controller_builder.h"
#include "dream/agent_host/python_controller_spec.h"
#include "dream/files/file_text.h"

namespace dream::bridge {

void KeepControllerModule(const run_config::RunConfig& config, const files::OutputFolder& out) {
  if (!agent_host::IsPythonController(config)) return;
  const agent_host::PythonControllerBuilder controller(config.controller, config.num_robots);
  const std::filesystem::path written = std::filesystem::path(controller.module_as_written()).lexically_normal();
  // An absolute path stays valid as written; a relative one never leaves the
  // config's folder (PythonControllerBuilder refuses that).
  if (written.is_absolute()) return;
  out.WriteFileInSubfolders(written.string(), files::ReadFileText(controller.module_path()));
}

void KeepRealismFile(const run_config::RunConfig& config, const files::OutputFolder& out) {
  if (config.realism_file_as_written.empty()) return;
  const std::filesystem::path written = std::filesystem::path(config.realism_file_as_written).lexically_normal();
  if (written.is_absolute()) return;
  out.WriteFileInSubfolders(written.string(), files::ReadFileText(config.realism_file));
}

}  // namespace dream::bridge
