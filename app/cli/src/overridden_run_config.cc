// OverriddenConfig's members that need the whole run (RunConfig, and so the
// world's library): apart from overridden_config.cc, in dream_sweep, so the
// agent process, which reads only the controller's part, does not link them.
#include "dream/config/config_error.h"
#include "dream/run_config/run_config.h"
#include "dream/config_overrides/overridden_config.h"
#include "dream/workflows/sweep_plan.h"

namespace dream::config_overrides {

run_config::RunConfig OverriddenConfig::Load() const {
  // Overrides are checked in memory: an overridden value keeps its key's line in the file.
  return LoadWith(&run_config::LoadRunConfig);
}

std::string OverriddenConfig::FolderText(const run_config::RunConfig& config) const {
  if (overrides_.empty()) return run_config::RunFolderConfigText(config, text_);
  return run_config::RunFolderConfigText(
      config, workflows::SweepPlan::EmitConfig(root_, path_ + " with " + OptionsText() +
                                               " (the values below include them; comments were not kept)."));
}

}  // namespace dream::config_overrides
