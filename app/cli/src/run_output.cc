#include "run_output.h"

#include "dream/run_config/startup_drive_check.h"

#include <spdlog/spdlog.h>

#include "dream/config/config_error.h"
#include "dream/process/data_files.h"
#include "dream/config_overrides/overridden_config.h"
#include "dream/run_config/run_config.h"
#include "dream/files/run_folder_choice.h"

namespace dream::cli {

std::unique_ptr<session::RunSession> OpenRunSession(const RunArgs& args) {
  const config_overrides::OverriddenConfig overridden(args.config_path, args.seed, args.sets);
  run_config::RunConfig config = overridden.LoadWith(&run_config::LoadRunConfig);
  if (args.steps != 0) {
    if (args.steps < 1) throw std::invalid_argument("--steps must be >= 1, got " + std::to_string(args.steps));
    config.sim.max_steps = args.steps;
  }
  if (!args.mode.empty()) config.sim.mode = config::ParseWorldMode(args.mode);
  if (args.all_steps) config.sim.stop_when_done = false;
  if (args.pace >= 0.0) {
    config.sim.pace = args.pace;
  } else if (args.view) {
    config.sim.pace = 1.0;  // --view: watched in real time unless --pace says otherwise
  }
  session::RunSession::Options options;
  options.steps_from_command_line = args.steps != 0;
  // -q/--quiet set the level to warn: a clean run's report is left out too.
  options.quiet = spdlog::get_level() >= spdlog::level::warn;
  options.stop = &StopFlag();
  options.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  auto run = std::make_unique<session::RunSession>(std::move(config), options);
  try {
    run->CheckAgents();
  } catch (const config::ConfigError& e) {
    throw config::ConfigError(overridden.Noted(e.what()));
  }
  return run;
}

void CheckStartupDrive(const run_config::RunConfig& config) {
  const run_config::StartupDriveCheck check = run_config::StartupDriveCheck::Of(config);
  if (const std::string refusal = check.Refusal(); !refusal.empty()) throw config::ConfigError(refusal);
  if (!check.AllSettled()) spdlog::warn("{}", check.Message());
}

run_config::RunConfig LoadConfig(const RunArgs& args) { return OpenRunSession(args)->config(); }

std::string ConfigTextForRunFolder(const RunArgs& args, const run_config::RunConfig& config) {
  return run_config::RunFolderConfigText(
      config, config_overrides::OverriddenConfig(args.config_path, args.seed, args.sets).Text());
}

std::string PrepareOutputDir(const RunArgs& args, const run_config::RunConfig& config) {
  return files::RunFolderChoice(args.out_dir, "runs/" + config.name, args.overwrite).dir();
}

}  // namespace dream::cli
