#include "dream/run_config/startup_drive_check.h"

#include "dream/world/startup_drive.h"

namespace dream::run_config {

StartupDriveCheck StartupDriveCheck::Of(const RunConfig& config) {
  StartupDriveCheck check;
  check.name_ = config.name;
  check.start_ = config.start;
  check.applies_ = !config.sim_only;
  if (check.applies_) check.trials_ = world::StartupDriveTrials::Try(config.world, config.initial_poses, config.seed);
  return check;
}

bool StartupDriveCheck::Refuses() const {
  return applies_ && start_ == WorldStart::kPlaced && trials_.tried() > 0 && !trials_.results().front().settled;
}

std::string StartupDriveCheck::Message() const {
  if (AllSettled()) return "";
  return name_ + ": " + trials_.Describe() +
         ". The lab drives the robots from random charger slots onto the start poses with its barrier "
         "certificate before every experiment, and rejects an experiment whose robots do not arrive "
         "(check-submission gives up after " + std::to_string(world::StartupDrive::MaxSteps()) +
         " steps): spread the start poses (e.g. initial_poses: {generate: {lab_safe: true}})";
}

}  // namespace dream::run_config
