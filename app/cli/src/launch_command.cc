#include <spdlog/spdlog.h>

#include <csignal>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include <filesystem>

#include "command_line.h"
#include "dream/session/run_reporter.h"
#include "dream/session/run_session.h"
#include "dream/workflows/agent_reports.h"
#include "dream/files/file_text.h"
#include "dream/files/output_folder_lock.h"
#include "commands.h"
#include "dream/process/data_files.h"
#include "dream/process/process_group.h"
#include "dream/workflows/run_workflow.h"
#include "script_command.h"
#include "shared_options.h"

namespace dream::cli {

// Measured: the simulator and a C++ agent peak at 13 open descriptors under
// udpm (LCM's sockets and pipes, the log, the lock, stdio); room for Python agents.
constexpr int kDescriptorsPerProcess = 24;

int RunLaunch(const RunArgs& args) {
  if (IsScriptPath(args.config_path) || !ScriptOfConfig(args.config_path).empty()) {
    throw std::invalid_argument(
        "dream launch " + args.config_path +
        ": a Robotarium script is one program that drives every robot itself, as on the Robotarium, so it has no "
        "agent per robot to launch; `dream run " +
        args.config_path +
        "` already runs it as its own process beside the simulator, over udpm (--lcm-url), so lcm-spy and dream view "
        "see it as any run (docs/robotarium-scripts.md)");
  }
  process::ProcessGroup::RequireDescriptors(kDescriptorsPerProcess);
  // Check the config here, so a mistake is reported once, not by N+1 children.
  const workflows::RunWorkflow workflow(process::DataFiles::PythonRuntimeDir(), StopFlag());
  const std::unique_ptr<session::RunSession> session = workflow.Open(args);
  const auto& config = session->config();
  workflows::RunWorkflow::CheckStartupDrive(config);
  // Chosen once, here: the simulator gets it as --out, so a numbered folder
  // (runs/<name>_2) is not chosen again, differently, by the child.
  const std::string out_dir = workflows::RunWorkflow::PrepareOutputDir(args, config);
  const std::string self = process::SelfExecutable();
  std::vector<std::string> common = {args.config_path};
  if (!args.lcm_url.empty()) common.push_back("--lcm-url=" + args.lcm_url);
  // The same overrides for the simulator and every agent, so all build the
  // same run (agents read the config too: robots, controller, seed).
  if (args.seed >= 0) common.push_back("--seed=" + std::to_string(args.seed));
  for (const std::string& set : args.sets) common.insert(common.end(), {"--set", set});
  // The children log (and show progress) as quietly or verbosely as this process.
  if (!spdlog::should_log(spdlog::level::info)) common.push_back("--quiet");
  if (spdlog::should_log(spdlog::level::debug)) common.push_back("--verbose");

  process::ProcessGroup children;
  std::vector<std::string> sim_argv = {self, "sim"};
  sim_argv.insert(sim_argv.end(), common.begin(), common.end());
  sim_argv.push_back("--out=" + out_dir);  // holds no run now (an earlier one was refused or removed)
  if (args.steps != 0) sim_argv.push_back("--steps=" + std::to_string(args.steps));
  if (!args.mode.empty()) sim_argv.push_back("--mode=" + args.mode);
  if (args.all_steps) sim_argv.push_back("--all-steps");
  if (args.pace >= 0.0) sim_argv.push_back("--pace=" + std::to_string(args.pace));
  // The simulator writes the folder this process has locked: it inherits the lock.
  const int lock_fd = files::OutputFolderLock::DescriptorOf(out_dir);
  const pid_t sim = children.Start(
      sim_argv, std::string(),
      {std::string(files::OutputFolderLock::kInheritedVariable) + "=" + std::to_string(lock_fd)}, lock_fd);
  std::filesystem::create_directories(
      std::filesystem::path(workflows::AgentReports::PathFor(out_dir, 0)).parent_path());
  std::vector<pid_t> agents;
  for (int id = 0; id < config.num_robots; ++id) {
    std::vector<std::string> agent_argv = {process::DataFiles::AgentBinary()};
    agent_argv.insert(agent_argv.end(), common.begin(), common.end());
    agent_argv.push_back("--robots=" + std::to_string(id));
    agent_argv.push_back("--report=" + workflows::AgentReports::PathFor(out_dir, id));
    agents.push_back(children.Start(agent_argv));
  }
  spdlog::info("launched the simulator and {} agent processes", agents.size());

  int sim_exit = -1;
  while ((sim_exit = children.WaitFor(sim, 0.1)) < 0) {
    if (StopFlag().load()) children.SignalAll(SIGINT);
  }
  int failed_agents = 0;
  for (pid_t agent : agents) {
    const int code = children.WaitFor(agent, 5.0);
    if (code != 0) ++failed_agents;
  }
  if (failed_agents > 0) spdlog::warn("{} agent process(es) did not exit cleanly", failed_agents);
  if (sim_exit == kExitInterrupted) return sim_exit;
  // The agents' refusals join summary.json and the verdict; a verdict they
  // changed replaces the log's and goes on the bus again, so the log and a
  // viewer end on summary.json's.
  const workflows::AgentReports reports = workflows::AgentReports::Read(out_dir, config.num_robots);
  const int exit_code = workflows::AgentReports::Merge(*session, out_dir, reports, sim_exit);
  workflows::AgentReports::ResendVerdict(*session, out_dir, reports, args.lcm_url, exit_code);
  return exit_code;
}

void DeclareLaunchCommand(CommandLine& line) {
  AddRunCommand(line, "launch",
                "Run the simulator and one agent process per robot over udpm.\n"
                "Example: dream launch config/go_to_goal.yaml --seed 7",
                RunLaunch, "LCM URL (default $LCM_DEFAULT_URL)");
}

}  // namespace dream::cli
