#pragma once

#include <memory>
#include <string>

#include "commands.h"
#include "dream/run_config/run_config.h"
#include "dream/node/run_outcome.h"
#include "dream/session/run_result.h"
#include "dream/session/run_session.h"
#include "dream/world/run_judgement.h"
#include "dream/world/run_report.h"

namespace dream::cli {

/// Loads the config, applies the command-line overrides (--seed, --set,
/// --steps, --mode, --all-steps) and opens its run: the session builds the
/// controller factory once, which checks the controller section (with
/// RunSession::CheckAgents), so a mistake stops every command (sim, launch)
/// before anything starts or any folder is made.
/// @throws config::ConfigError or std::invalid_argument with a clear message.
std::unique_ptr<session::RunSession> OpenRunSession(const RunArgs& args);

/// The Robotarium's start-up drive on the run's start poses, from several
/// random placements (run_config::StartupDriveCheck), before anything runs:
/// a warning naming robots and distances when a placement does not settle;
/// with `world.start: placed` a run whose own drive does not settle is
/// refused (config::ConfigError).
void CheckStartupDrive(const run_config::RunConfig& config);

/// The checked config alone (OpenRunSession), for commands that run no world here (dream sweep).
run_config::RunConfig LoadConfig(const RunArgs& args);

/// What the run folder's config.yaml holds: the config file, with --seed and
/// --set applied when given (OverriddenConfig::Text), so the folder
/// alone reruns the run.
std::string ConfigTextForRunFolder(const RunArgs& args, const run_config::RunConfig& config);

/// The output folder (RunFolderChoice): --out, else runs/<name>, or
/// runs/<name>_2, ... when that holds a run; a folder holding a run only with
/// --overwrite. Created if missing. @throws std::runtime_error naming the folder.
std::string PrepareOutputDir(const RunArgs& args, const run_config::RunConfig& config);

}  // namespace dream::cli
