#include "dream/bridge/controller_module_copy.h"

#include <filesystem>
#include <memory>

#include "dream/agent_host/controller_registry.h"
#include "dream/config/controller_config.h"
#include "dream/files/file_text.h"
#include "dream/kind_api/controller_kind.h"

namespace dream::bridge {

void KeepControllerModule(const run_config::RunConfig& config, const files::OutputFolder& out) {
  const std::shared_ptr<const kind_api::ControllerKind> kind = agent_host::ControllerRegistry::KindOf(config);
  if (kind == nullptr || kind->file_key.empty()) return;
  kind->make_builder(config.controller, config.num_robots);  // checks the file as a run does
  const config::ConfigNode node = config.controller.Required(kind->file_key);
  const std::filesystem::path written = std::filesystem::path(node.AsString()).lexically_normal();
  // An absolute path stays valid as written; a relative one never leaves the
  // config's folder (FileBesideConfig refuses that).
  if (written.is_absolute()) return;
  out.WriteFileInSubfolders(written.string(),
                            files::ReadFileText(config::FileBesideConfig(node, kind->file_key).string()));
}

void KeepRealismFile(const run_config::RunConfig& config, const files::OutputFolder& out) {
  const std::string copy = run_config::RealismFileInRunFolder(config);
  if (copy.empty()) return;
  out.WriteFileInSubfolders(copy, files::ReadFileText(config.realism_file));
}

}  // namespace dream::bridge
