#include "run_output.h"

#include <spdlog/spdlog.h>

#include "dream/config/config_error.h"
#include "data_files.h"
#include "hosted_agents.h"
#include "dream/config_overrides/overridden_config.h"
#include "dream/run_config/run_config.h"
#include "run_folder_choice.h"

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
  options.python_runtime_dir = DataFiles::PythonRuntimeDir();
  auto run = std::make_unique<session::RunSession>(std::move(config), options);
  try {
    HostedAgents::Check(run->config(), run->factory(), run->config().sim.start_timeout_s);
  } catch (const config::ConfigError& e) {
    throw config::ConfigError(overridden.Noted(e.what()));
  }
  return run;
}

run_config::RunConfig LoadConfig(const RunArgs& args) { return OpenRunSession(args)->config(); }

std::string ConfigTextForRunFolder(const RunArgs& args, const run_config::RunConfig& config) {
  return run_config::RunFolderConfigText(config, config_overrides::OverriddenConfig(args.config_path, args.seed, args.sets).Text());
}

std::string PrepareOutputDir(const RunArgs& args, const run_config::RunConfig& config) {
  return RunFolderChoice(args.out_dir, "runs/" + config.name, args.overwrite).dir();
}

int ExitCodeFor(const session::RunResult& result) {
  if (!result.summary_written) return kExitRunFailed;  // the session said which output, and why
  const int exit_code = ExitCodeFor(result.outcome, result.judgement);
  return result.picture_failed ? kExitRunFailed : exit_code;
}

int ExitCodeFor(const node::RunOutcome& outcome, const world::RunJudgement& judgement) {
  const int ended = ExitCodeFor(outcome, judgement.report());
  if (ended != kExitOk && ended != kExitRejected) return ended;  // did not finish, interrupted
  // A robot whose controller failed makes the run fail, whatever the rest did.
  if (!outcome.robot_faults.empty()) return kExitRunFailed;
  switch (judgement.verdict()) {
    case world::RunVerdict::kRejected:
      return kExitRejected;
    case world::RunVerdict::kNotReady:
      return kExitNotReady;
    case world::RunVerdict::kClean:
    case world::RunVerdict::kWarning:
      break;
  }
  return kExitOk;
}

int ExitCodeFor(const node::RunOutcome& outcome, const world::RunReport& report) {
  switch (outcome.end) {
    case node::RunOutcome::End::kFinished:
      return report.verdict == world::RunVerdict::kRejected ? kExitRejected : kExitOk;
    case node::RunOutcome::End::kInterrupted:
      return kExitInterrupted;
    default:
      spdlog::error("{}", outcome.reason);
      return kExitRunFailed;
  }
}

}  // namespace dream::cli
