#include "dream/session/realism_notice.h"

namespace dream::session {

std::string RealismNotice(const run_config::RunConfig& config) {
  if (config.realism.IsIdeal()) return "";
  std::string name = "custom";
  for (const std::string& preset : world::RealismParams::PresetNames()) {
    world::RealismParams params;
    if (world::RealismParams::FromPreset(preset, &params) && params == config.realism) name = preset;
  }
  if (!config.realism_file.empty()) name += ", from " + config.realism_file;
  return "realism: " + name +
         " (not the official simulator's ideal world: modelled tracking noise, delays and wheels; the models: "
         "summary.json realism)";
}

}  // namespace dream::session
