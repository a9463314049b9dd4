#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <utility>

#include "dream/run_config/run_config.h"
#include "dream/session/run_session.h"
#include "dream/workflows/run_options.h"

namespace dream::workflows {

/// `dream run` (the world and every agent in this process) and `dream sim`
/// (the world alone, agents elsewhere), and the steps every command that runs
/// an experiment shares (dream launch and sweep too): the config loaded with
/// its overrides and checked, the start-up drive checked, the run folder chosen.
class RunWorkflow {
 public:
  /// `python_runtime_dir`: DREAM's Python package (a Python controller's
  /// metrics and goal); `stop` (Ctrl-C) ends the run and every wait.
  RunWorkflow(std::string python_runtime_dir, const std::atomic<bool>& stop)
      : python_runtime_dir_(std::move(python_runtime_dir)), stop_(stop) {}

  /// Loads the config, applies the overrides (--seed, --set, --steps, --mode,
  /// --all-steps, --pace) and opens its run: the session builds the
  /// controller factory once and checks the controller section
  /// (RunSession::CheckAgents), so a mistake stops every command before
  /// anything starts or any folder is made.
  /// @throws config::ConfigError or std::invalid_argument with a clear message.
  std::unique_ptr<session::RunSession> Open(const RunOptions& options) const;

  /// The checked config alone (Open), for commands that run no world here (dream sweep).
  run_config::RunConfig LoadConfig(const RunOptions& options) const { return Open(options)->config(); }

  /// The Robotarium's start-up drive on the run's start poses, from several
  /// random placements (run_config::StartupDriveCheck), before anything runs:
  /// a warning naming robots and distances when a placement does not settle;
  /// with `world.start: placed` a run whose own drive does not settle is
  /// refused (config::ConfigError).
  static void CheckStartupDrive(const run_config::RunConfig& config);

  /// What the run folder's config.yaml holds: the config file, with --seed and
  /// --set applied when given (OverriddenConfig::Text), so the folder alone
  /// reruns the run.
  static std::string ConfigTextForRunFolder(const RunOptions& options, const run_config::RunConfig& config);

  /// The output folder (files::RunFolderChoice): --out, else runs/<name>, or
  /// runs/<name>_2, ... when that holds a run; a folder holding a run only
  /// with --overwrite. Created if missing. @throws std::runtime_error naming the folder.
  static std::string PrepareOutputDir(const RunOptions& options, const run_config::RunConfig& config);

  /// dream run: the world and every robot's agent on one bus (memq:// unless
  /// `lcm_url`), with the live page when `view`. Returns the exit code (session::ExitCode).
  int RunEmbedded(const RunOptions& options) const;
  /// dream sim: the world alone on `lcm_url` ($LCM_DEFAULT_URL when empty).
  /// Returns the exit code.
  int RunSimOnly(const RunOptions& options) const;

 private:
  std::string python_runtime_dir_;
  const std::atomic<bool>& stop_;
};

}  // namespace dream::workflows
