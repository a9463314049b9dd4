#include "dream/run_config/startup_drive_check.h"

#include "dream/run_config/startup_drive_cache.h"
#include "dream/world/printf_text.h"
#include "dream/world/startup_drive.h"

namespace dream::run_config {

StartupDriveCheck StartupDriveCheck::Of(const RunConfig& config) {
  StartupDriveCheck check;
  check.name_ = config.name;
  check.start_ = config.start;
  check.lab_safe_spacing_m_ = config.lab_safe_spacing_m;
  check.applies_ = !config.sim_only;
  if (check.applies_) {
    // The drives of start poses tried before (another run or export of the config, a test) are not run again.
    const StartupDriveCache cache(StartupDriveCache::DefaultFolder());
    check.trials_ = cache.Trials(config.world, config.initial_poses, config.seed);
  }
  return check;
}

std::string StartupDriveCheck::Refusal() const {
  if (AllSettled()) return "";
  if (lab_safe_spacing_m_ > 0.0) {
    return name_ + ": initial_poses.generate.lab_safe: the start poses generated at least " +
           world::PrintfText("%.3f", lab_safe_spacing_m_) +
           " m apart (min_spacing_m) are not lab-safe: " + trials_.Describe() +
           "; raise min_spacing_m, try another seed or use fewer robots";
  }
  if (start_ == WorldStart::kPlaced && !trials_.results().front().settled) {
    return Message() + "; world.start: placed runs that drive first, so this run cannot start";
  }
  return "";
}

std::string StartupDriveCheck::Message() const {
  if (AllSettled()) return "";
  return name_ + ": " + trials_.Describe() +
         ". The lab drives the robots from random charger slots onto the start poses with its barrier "
         "certificate before every experiment, and rejects an experiment whose robots do not arrive "
         "(check-submission gives up after " +
         std::to_string(world::StartupDrive::MaxSteps()) +
         " steps): spread the start poses (e.g. initial_poses: {generate: {lab_safe: true}})";
}

}  // namespace dream::run_config
