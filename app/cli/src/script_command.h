#pragma once

#include <string>
#include <vector>

#include "commands.h"
#include "dream/workflows/lab_replay_workflow.h"

namespace dream::cli {

/// Whether `dream run` was given a Robotarium script (a .py file) rather than a config.
bool IsScriptPath(const std::string& path);

/// The Robotarium script a run config names (`script:`, which dream run
/// SCRIPT.py and dream sweep SCRIPT.py write), resolved from the config's
/// folder; "" when it names none (or `path` is no config file).
std::string ScriptOfConfig(const std::string& path);

/// `dream run SCRIPT.py [-- ARGS...]` (docs/robotarium-scripts.md): the script
/// runs in its own process with DREAM's rps, in the run folder; the world is
/// workflows::ScriptRunWorkflow's. Returns the run's exit code (session::ExitCodeOf),
/// 4 when the script failed or ended before it made its Robotarium.
/// `args.config_path` may also be a config naming the script (ScriptOfConfig).
int RunScript(const RunArgs& args, const std::vector<std::string>& script_args);

/// `dream lab-replay LAB_DIR` of a Robotarium script's lab run (its
/// config.yaml names `script:`): the script runs again, as under dream run,
/// in the replay's folder on a bus of its own, as the agent of every robot,
/// and the world is the lab run replayed (workflows::LabReplayWorkflow with
/// script_agent). Returns the replay's exit code.
int RunScriptLabReplay(workflows::LabReplayWorkflow::Options options);

}  // namespace dream::cli
