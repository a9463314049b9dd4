#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace dream::cli {

/// Exit codes scripts can rely on (also in `dream --help`).
enum ExitCode : int {
  kExitOk = 0,              ///< the run finished; the Robotarium would accept it
  kExitInputError = 1,      ///< bad config, file or argument; nothing was run
  kExitUsage = 2,           ///< unknown subcommand or option
  kExitRejected = 3,        ///< the run finished but has hard errors (the Robotarium would reject it)
  kExitRunFailed = 4,       ///< the run did not finish (agents missing, lost world, I/O error)
  kExitInterrupted = 130,   ///< Ctrl-C / SIGTERM; outputs are complete up to the interruption
};

/// Set by SIGINT/SIGTERM; every loop polls it.
std::atomic<bool>& StopFlag();
/// Makes SIGINT and SIGTERM set StopFlag().
void InstallStopSignals();

/// Agents run in the lean dream-agent executable (no simulator, pictures or
/// their libraries: a third of the memory). `dream agent ...` replaces itself
/// with `dream-agent ...`, found next to `dream`. Returns only on failure.
int ExecAgentBinary(int argc, char** argv);
/// The dream-agent executable next to the running one.
std::string AgentBinaryPath();

struct RunArgs {
  std::string config_path;
  std::string out_dir;          ///< empty: runs/<name>
  std::string lcm_url;          ///< empty: memq:// for run, else LCM_DEFAULT_URL
  long long steps = 0;          ///< 0: the config's
  std::string mode;             ///< empty: the config's
  bool all_steps = false;       ///< run every step even when all robots report done
};

struct AgentArgs {
  std::string config_path;
  std::string robots = "all";   ///< "all", "3", "0,2,5" or "0-4"
  std::string lcm_url;
  double idle_timeout_s = 60.0;
};

/// A random identifier for this process's agents (see velocity_command_t.agent_id).
int64_t NewAgentId();

int RunEmbedded(const RunArgs& args);
int RunSimOnly(const RunArgs& args);
int RunAgents(const AgentArgs& args);
int RunLaunch(const RunArgs& args);
int RunLogInfo(const std::string& path);
/// Compares the payloads of each channel matching `channel_regex`, in order
/// (timestamps ignored). Exit 0 when equal.
int RunLogDiff(const std::string& a, const std::string& b, const std::string& channel_regex);
int RunSpy(const std::string& log_path, const std::string& lcm_url, bool print_command_only);

/// Parses "all", "3", "0,2,5", "0-4" into sorted unique ids < num_robots.
/// @throws std::invalid_argument naming the bad part.
std::vector<int> ParseRobotList(const std::string& text, int num_robots);

}  // namespace dream::cli
