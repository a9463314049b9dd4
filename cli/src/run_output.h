#pragma once

#include <string>

#include "commands.h"
#include "dream/config/run_config.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/sim/run_outcome.h"
#include "dream/sim/run_report.h"

namespace dream::cli {

/// Loads the config and applies command-line overrides (--seed, --set,
/// --steps, --mode, --all-steps).
/// @throws config::ConfigError or std::invalid_argument with a clear message.
config::RunConfig LoadConfig(const RunArgs& args);

/// What the run folder's config.yaml holds: the config file, with --seed and
/// --set applied when given (OverriddenConfig::FolderText), so the folder
/// alone reruns the run.
std::string ConfigTextForRunFolder(const RunArgs& args, const config::RunConfig& config);

/// The output folder (RunFolderChoice): --out, else runs/<name>, or
/// runs/<name>_2, ... when that holds a run; a folder holding a run only with
/// --overwrite. Created if missing. @throws std::runtime_error naming the folder.
std::string PrepareOutputDir(const RunArgs& args, const config::RunConfig& config);

/// Runs the simulator on `lcm` until the run ends, writing <out_dir>/config.yaml
/// (`config_text`, see ConfigTextForRunFolder), <out_dir>/run.lcmlog and <out_dir>/summary.json
/// (all atomically), and prints the Robotarium verdict. Returns the process
/// exit code: kExitRunFailed when the run failed (e.g. its log could not be
/// written: summary.json then says why, and the log keeps every whole event
/// before the failure) or an output cannot be written (one line says which).
int RunWorld(lcm::LcmInterface& lcm, const config::RunConfig& config, const std::string& config_text,
             const std::string& out_dir);

/// The exit code for how a run ended and what the Robotarium would make of
/// it (see ExitCode); logs the reason when the run did not finish.
int ExitCodeFor(const sim::RunOutcome& outcome, const sim::RunReport& report);

}  // namespace dream::cli
