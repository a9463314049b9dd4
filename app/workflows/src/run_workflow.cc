#include "dream/workflows/run_workflow.h"

#include <spdlog/spdlog.h>

#include <iostream>
#include <stdexcept>

#include "dream/config/config_error.h"
#include "dream/config_overrides/overridden_config.h"
#include "dream/files/run_folder_choice.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/run_config/startup_drive_check.h"
#include "dream/session/exit_code.h"
#include "dream/session/run_exit_code.h"
#include "dream/workflows/run_view.h"

namespace dream::workflows {

std::unique_ptr<session::RunSession> RunWorkflow::Open(const RunOptions& args) const {
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
  options.stop = &stop_;
  options.python_runtime_dir = python_runtime_dir_;
  auto run = std::make_unique<session::RunSession>(std::move(config), options);
  try {
    run->CheckAgents();
  } catch (const config::ConfigError& e) {
    throw config::ConfigError(overridden.Noted(e.what()));
  }
  return run;
}

void RunWorkflow::CheckStartupDrive(const run_config::RunConfig& config) {
  const run_config::StartupDriveCheck check = run_config::StartupDriveCheck::Of(config);
  if (const std::string refusal = check.Refusal(); !refusal.empty()) throw config::ConfigError(refusal);
  if (!check.AllSettled()) spdlog::warn("{}", check.Message());
}

std::string RunWorkflow::ConfigTextForRunFolder(const RunOptions& args, const run_config::RunConfig& config) {
  return run_config::RunFolderConfigText(
      config, config_overrides::OverriddenConfig(args.config_path, args.seed, args.sets).Text());
}

std::string RunWorkflow::PrepareOutputDir(const RunOptions& args, const run_config::RunConfig& config) {
  return files::RunFolderChoice(args.out_dir, "runs/" + config.name, args.overwrite).dir();
}

int RunWorkflow::RunEmbedded(const RunOptions& args) const {
  const std::unique_ptr<session::RunSession> run = Open(args);
  const run_config::RunConfig& config = run->config();
  CheckStartupDrive(config);
  // One process: the world and every agent share one bus, memq:// unless the
  // user asks for a real transport.
  const RunView::Keep keep = RunView::Keep::Parse(args.view_keep);  // a bad value before anything runs
  lcm::LcmBus bus(args.lcm_url.empty() ? "memq://" : lcm::ResolveLcmUrl(args.lcm_url));
  const std::string out_dir = PrepareOutputDir(args, config);
  std::unique_ptr<RunView> view;
  if (args.view) {
    view = std::make_unique<RunView>(bus, config, args.view_bind, args.view_port, args.view_fps, python_runtime_dir_,
                                     stop_);
  }
  // Before the agents start: none of them waits on a world that waits on a browser.
  if (view && args.view_wait && !view->WaitForBrowser(args.view_wait_timeout_s)) {
    std::cout << "dream run: stopped while waiting for a browser; nothing was run" << std::endl;
    return session::kExitInterrupted;
  }
  const session::RunResult result = run->RunWithAgents(bus, {out_dir, ConfigTextForRunFolder(args, config)});
  if (view) {
    view->ServeReplayOf(out_dir);
    view->KeepServing(keep);  // Ctrl-C here ends the serving, not the run: its exit code stands
  }
  return session::ExitCodeOf(result);
}

int RunWorkflow::RunSimOnly(const RunOptions& args) const {
  const std::unique_ptr<session::RunSession> run = Open(args);
  CheckStartupDrive(run->config());
  lcm::LcmBus bus(lcm::ResolveLcmUrl(args.lcm_url));
  const std::string out_dir = PrepareOutputDir(args, run->config());
  return session::ExitCodeOf(run->Run(bus, {out_dir, ConfigTextForRunFolder(args, run->config())}));
}

}  // namespace dream::workflows
