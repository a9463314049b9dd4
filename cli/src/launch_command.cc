#include <spdlog/spdlog.h>

#include <csignal>
#include <chrono>
#include <memory>
#include <thread>

#include "command_line.h"
#include "dream/sim/output_folder_lock.h"
#include "commands.h"
#include "process_group.h"
#include "run_output.h"
#include "shared_options.h"

namespace dream::cli {

// Measured: the simulator and a C++ agent peak at 13 open descriptors under
// udpm (LCM's sockets and pipes, the log, the lock, stdio); room for Python agents.
constexpr int kDescriptorsPerProcess = 24;

int RunLaunch(const RunArgs& args) {
  ProcessGroup::RequireDescriptors(kDescriptorsPerProcess);
  // Check the config here, so a mistake is reported once, not by N+1 children.
  const config::RunConfig config = LoadConfig(args);
  // Chosen once, here: the simulator gets it as --out, so a numbered folder
  // (runs/<name>_2) is not chosen again, differently, by the child.
  const std::string out_dir = PrepareOutputDir(args, config);
  const std::string self = SelfExecutable();
  std::vector<std::string> common = {args.config_path};
  if (!args.lcm_url.empty()) common.push_back("--lcm-url=" + args.lcm_url);
  // The same overrides for the simulator and every agent, so all build the
  // same run (agents read the config too: robots, controller, seed).
  if (args.seed >= 0) common.push_back("--seed=" + std::to_string(args.seed));
  for (const std::string& set : args.sets) common.insert(common.end(), {"--set", set});
  // The children log (and show progress) as quietly or verbosely as this process.
  if (!spdlog::should_log(spdlog::level::info)) common.push_back("--quiet");
  if (spdlog::should_log(spdlog::level::debug)) common.push_back("--verbose");

  ProcessGroup children;
  std::vector<std::string> sim_argv = {self, "sim"};
  sim_argv.insert(sim_argv.end(), common.begin(), common.end());
  sim_argv.push_back("--out=" + out_dir);  // holds no run now (an earlier one was refused or removed)
  if (args.steps != 0) sim_argv.push_back("--steps=" + std::to_string(args.steps));
  if (!args.mode.empty()) sim_argv.push_back("--mode=" + args.mode);
  if (args.all_steps) sim_argv.push_back("--all-steps");
  // The simulator writes the folder this process has locked: it inherits the lock.
  const int lock_fd = sim::OutputFolderLock::DescriptorOf(out_dir);
  const pid_t sim = children.Start(
      sim_argv, std::string(),
      {std::string(sim::OutputFolderLock::kInheritedVariable) + "=" + std::to_string(lock_fd)}, lock_fd);
  std::vector<pid_t> agents;
  for (int id = 0; id < config.num_robots; ++id) {
    std::vector<std::string> agent_argv = {AgentBinaryPath()};
    agent_argv.insert(agent_argv.end(), common.begin(), common.end());
    agent_argv.push_back("--robots=" + std::to_string(id));
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
  return sim_exit;
}

void DeclareLaunchCommand(CommandLine& line) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* command = line.AddCommand(
      "launch",
      "Run the simulator and one agent process per robot over udpm.\n"
      "Example: dream launch config/go_to_goal.yaml --seed 7",
      [args] { return RunLaunch(*args); });
  AddRunOptions(command, args.get(), "LCM URL (default $LCM_DEFAULT_URL)");
}

}  // namespace dream::cli
