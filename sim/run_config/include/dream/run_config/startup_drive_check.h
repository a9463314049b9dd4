#pragma once

#include <string>

#include "dream/run_config/run_config.h"
#include "dream/world/startup_drive_trials.h"

namespace dream::run_config {

/// What the Robotarium's start-up drive makes of a run's start poses, tried
/// from world::StartupDriveTrials::kPlacements random charger placements
/// seeded by the run's seed: what `dream run`, `sim`, `launch`, `sweep` and
/// `export` ask before step 0 (config/README.md#the-start-up-drive-worldstart-and-lab_safe).
class StartupDriveCheck {
 public:
  /// Drives `config`'s start poses; a `sim_only` run (which the lab never
  /// starts) is not driven.
  static StartupDriveCheck Of(const RunConfig& config);

  /// False for a sim_only run: nothing was tried.
  bool applies() const { return applies_; }
  /// Every placement settled (true when nothing was tried).
  bool AllSettled() const { return !applies_ || trials_.AllSettled(); }
  /// Why the run may not start ("" when it may): `world.start: placed` and its
  /// own drive (placement 0) did not settle, or `lab_safe` start poses that
  /// some placement did not settle.
  std::string Refusal() const;
  /// "<name>: the Robotarium's start-up drive settled from 3 of 5 ...; ..."
  /// with what to do; empty when every placement settled.
  std::string Message() const;
  const world::StartupDriveTrials& trials() const { return trials_; }

 private:
  std::string name_;
  WorldStart start_ = WorldStart::kExact;
  double lab_safe_spacing_m_ = 0.0;
  bool applies_ = false;
  world::StartupDriveTrials trials_;
};

}  // namespace dream::run_config
