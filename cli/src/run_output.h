#pragma once

#include <string>

#include "commands.h"
#include "dream/config/run_config.h"
#include "dream/lcm/lcm_interface.h"
#include <nlohmann/json.hpp>

#include "dream/world/run_judgement.h"
#include "dream/node/run_outcome.h"
#include "dream/world/run_report.h"
#include "dream/world/world.h"

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
/// (all atomically), and prints the verdict (ReportRun). Returns the process
/// exit code (ExitCodeFor): kExitRunFailed also when an output cannot be
/// written (one line says which). `steps_from_command_line`: the step limit
/// is --steps, so a run stopped by it has its goal not judged.
int RunWorld(lcm::LcmInterface& lcm, const config::RunConfig& config, const std::string& config_text,
             const std::string& out_dir, bool steps_from_command_line = false);

/// After a run: judges it (JudgeRunAndGoal), writes <out_dir>/summary.json
/// with `world_fields` added and trajectories.png, prints the verdict with
/// its reasons. Returns the exit code.
int ReportRun(const config::RunConfig& config, const sim::RunOutcome& outcome, const sim::World& world,
              const std::string& out_dir, bool steps_from_command_line,
              const nlohmann::ordered_json& world_fields = nlohmann::ordered_json::object());

/// sim::JudgeRun with the lab verifier's count of robots outside the arena
/// re-counted on the log at `log_path`, plus the experiment's goal judged on
/// `summary` (which must hold "metrics"; ExperimentGoal), whose result is
/// added to it as "goal" (with "judged": false when --steps stopped the run
/// before the goal, which then is no reason).
sim::RunJudgement JudgeRunAndGoal(const config::RunConfig& config, const sim::RunOutcome& outcome,
                                  const sim::World& world, const std::string& log_path,
                                  nlohmann::ordered_json* summary, bool steps_from_command_line);

/// The exit code for how a run ended and what the Robotarium would make of
/// its poses (see ExitCode); logs the reason when the run did not finish.
int ExitCodeFor(const sim::RunOutcome& outcome, const sim::RunReport& report);
/// The same with every reason of the judgement: 130 interrupted, 4 did not
/// finish or a controller failed, 3 rejected, 5 not ready, else 0.
int ExitCodeFor(const sim::RunOutcome& outcome, const sim::RunJudgement& judgement);

}  // namespace dream::cli
