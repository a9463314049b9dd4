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

// --- the bridge to the Robotarium (bridge_commands.cc, docs/robotarium.md) ---

struct ExportArgs {
  std::string run_dir;          ///< a folder written by dream run
  std::string out_dir;          ///< empty: exports/<name>
  std::string config_path;      ///< empty: <run_dir>/config.yaml
  std::string strategy = "track";
  bool barriers = false;
  int settle_steps = 240;
};

struct ImportArgs {
  std::string result;           ///< dream_result.npy / .mat, or a folder holding one
  std::string export_dir;
  std::string out_dir;          ///< empty: runs/<name>_lab
};

struct LabReplayArgs {
  std::string lab_dir;          ///< a folder written by dream import
  std::string out_dir;          ///< empty: runs/<name>_lab_replay
  std::string lcm_url;          ///< empty: memq:// with in-process agents, else LCM_DEFAULT_URL
  long long steps = 0;          ///< 0: the whole lab run
  std::string mode;             ///< empty: the config's
  bool world_only = false;      ///< no in-process agents: they run elsewhere (dream agent)
};

struct CompareArgs {
  std::string first_dir;        ///< the simulated run
  std::string second_dir;       ///< the lab run
  std::string out_dir;          ///< empty: second_dir
};

struct CheckSubmissionArgs {
  std::string export_dir;
  std::string out_dir;          ///< empty: runs/<name>_check
  std::string run_dir;          ///< the simulated run to compare with; empty: the export's source run
  std::string simulator;        ///< a robotarium_python_simulator checkout; empty: $ROBOTARIUM_PYTHON_SIMULATOR
  std::string python;           ///< empty: the configured Python (/usr/bin/python3)
  bool standin = false;         ///< use the stand-in even when the official simulator is there
  bool require_official = false;
  bool skip_initialization = false;
};

int RunExport(const ExportArgs& args);
int RunImport(const ImportArgs& args);
int RunLabReplay(const LabReplayArgs& args);
int RunCompare(const CompareArgs& args);
int RunCheckSubmission(const CheckSubmissionArgs& args);

/// Parses "all", "3", "0,2,5", "0-4" into sorted unique ids < num_robots.
/// @throws std::invalid_argument naming the bad part.
std::vector<int> ParseRobotList(const std::string& text, int num_robots);

}  // namespace dream::cli
