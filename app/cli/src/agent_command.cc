#include <spdlog/spdlog.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>

#include "dream/hosting/hosted_agents.h"
#include "dream/config_overrides/overridden_config.h"
#include "command_line.h"
#include "commands.h"
#include "dream/process/data_files.h"
#include "dream/process/process_group.h"
#include "shared_options.h"
#include "dream/config/controller_config.h"
#include "dream/files/atomic_file.h"

namespace dream::cli {

double PeakResidentMegabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // "VmHWM:   7472 kB"
  }
  return 0.0;
}

std::vector<int> ParseRobotList(const std::string& text, int num_robots) {
  std::set<int> ids;
  auto parse_id = [&](const std::string& part) {
    size_t used = 0;
    int id = -1;
    try {
      id = std::stoi(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != part.size() || part.empty() || id < 0 || id >= num_robots) {
      throw std::invalid_argument("--robots: '" + part + "' is not a robot id of this run (0.." +
                                  std::to_string(num_robots - 1) + ")");
    }
    return id;
  };
  if (text == "all") {
    for (int id = 0; id < num_robots; ++id) ids.insert(id);
  } else {
    size_t start = 0;
    while (start <= text.size()) {
      const size_t comma = text.find(',', start);
      const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      const size_t dash = part.find('-');
      if (dash != std::string::npos && dash > 0) {
        const int first = parse_id(part.substr(0, dash));
        const int last = parse_id(part.substr(dash + 1));
        if (last < first) throw std::invalid_argument("--robots: range '" + part + "' is backwards");
        for (int id = first; id <= last; ++id) ids.insert(id);
      } else {
        ids.insert(parse_id(part));
      }
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return {ids.begin(), ids.end()};
}

namespace {

// Written to a temporary name and renamed, so dream launch never reads half
// a report; a failure is logged, not fatal: the run itself is done.
void WriteAgentReport(const std::string& path, const std::string& json) {
  try {
    files::WriteFileAtomically(path, json + "\n", files::Durability::kRenamedOnly);
  } catch (const std::runtime_error& e) {
    spdlog::error("cannot write the agents' report: {}", e.what());
  }
}

// world.<key> of the config as overridden (--set included): how long the
// world waits for an agent (agent_timeout_s) or for every agent at the start
// (start_timeout_s), which bound a Python controller's step and its setup().
// 0 when the config leaves it to the default (HostedAgents then uses that).
double WorldTimeout(const config::ConfigNode& root, const char* key) {
  const config::ConfigNode world = root.Optional("world");
  if (!world.IsDefined() || !world.IsMap() || !world.Has(key)) return 0.0;
  return world.Required(key).AsDouble();
}

}  // namespace

int RunAgents(const AgentArgs& args, const std::function<void()>& hand_over_plugins) {
  // The controller's part only: an agent does no world work (and does not link the world).
  const config_overrides::OverriddenConfig overridden(args.config_path, args.seed, args.sets);
  const config::ControllerConfig config = overridden.LoadController();
  if (!config.plugins.empty() && hand_over_plugins) hand_over_plugins();
  const std::vector<int> ids = ParseRobotList(args.robots, config.num_robots);
  auto host = std::make_unique<hosting::HostedAgents>(
      args.lcm_url, config, ids,
      python_host::PythonHostProcess::Limits{WorldTimeout(overridden.Document(), "agent_timeout_s"),
                                             WorldTimeout(overridden.Document(), "start_timeout_s"),
                                             args.idle_timeout_s});
  spdlog::info("agent for robot(s) {} of {} on {}", args.robots, config.name, host->url());
  const bool ended_by_world = host->Run(StopFlag(), args.idle_timeout_s);
  const std::string report = host->ReportJson();
  const int64_t last_step = host->last_step_answered();
  const std::string end_detail = host->end_detail();
  host.reset();  // a Python controllers' process is reaped: its peak is known
  // Peak resident memory, so per-agent memory can be checked
  // (docs/performance.md). VmHWM, not getrusage's ru_maxrss: the latter
  // survives execve and would report the launching process's size; but for
  // the reaped Python process (RUSAGE_CHILDREN), ru_maxrss is its own.
  const double here_mb = PeakResidentMegabytes();
  rusage children{};
  const double python_mb =
      ::getrusage(RUSAGE_CHILDREN, &children) == 0 ? static_cast<double>(children.ru_maxrss) / 1024.0 : 0.0;
  if (python_mb > 0.0) {
    spdlog::info(
        "agent for robot(s) {}: peak resident memory {:.1f} MB ({:.1f} MB here, {:.1f} MB in its Python "
        "process)",
        args.robots, here_mb + python_mb, here_mb, python_mb);
  } else {
    spdlog::info("agent for robot(s) {}: peak resident memory {:.1f} MB", args.robots, here_mb);
  }
  if (!args.report_path.empty()) WriteAgentReport(args.report_path, report);
  if (StopFlag().load()) return kExitInterrupted;
  if (!ended_by_world) return kExitRunFailed;
  spdlog::info("world ended the run at step {}: {}", last_step, end_detail);
  return kExitOk;
}

int ExecAgentBinary(int argc, char** argv) {
  const std::string binary = process::DataFiles::AgentBinary();
  // argv is "dream [-q|-v] agent ARGS...": run "dream-agent [-q|-v] ARGS...".
  std::vector<char*> args = {const_cast<char*>(binary.c_str())};
  bool skipped_subcommand = false;
  for (int i = 1; i < argc; ++i) {
    if (!skipped_subcommand && std::string(argv[i]) == "agent") {
      skipped_subcommand = true;
      continue;
    }
    args.push_back(argv[i]);
  }
  args.push_back(nullptr);
  ::execv(binary.c_str(), args.data());
  throw std::runtime_error("cannot start " + binary + " (" + std::strerror(errno) +
                           "); it is built and installed next to dream");
}

void DeclareAgentCommand(CommandLine& line) {
  // The options are parsed here too, so mistakes are reported before the
  // hand-over and `dream agent --help` works; dream-agent then parses the same
  // words, so the parsed AgentArgs go unused here.
  const auto [command, args] =
      line.AddCommand<AgentArgs>("agent",
                                 "Run the agents of some robots against whichever world is on the bus.\n"
                                 "Example: dream agent config/go_to_goal.yaml --robots 0-2",
                                 [&line](const AgentArgs&) { return ExecAgentBinary(line.argc(), line.argv()); });
  AddAgentOptions(command, args);
}

}  // namespace dream::cli
