#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dream/session/exit_code.h"
#include "dream/workflows/run_options.h"

namespace dream::cli {

class CommandLine;

// Exit codes: the one list every command uses (dream::session::ExitCode).
using session::ExitCode;
using session::kExitInputError;
using session::kExitInterrupted;
using session::kExitNotReady;
using session::kExitOk;
using session::kExitRejected;
using session::kExitRunFailed;
using session::kExitUsage;

/// Set by SIGINT/SIGTERM; every loop polls it.
std::atomic<bool>& StopFlag();
/// Makes SIGINT, SIGTERM and SIGHUP set StopFlag(), and ignores SIGXFSZ
/// (a write past a file size limit then fails, and the recorder says so).
void InstallStopSignals();

/// Agents run in the lean dream-agent executable (no simulator, pictures or
/// their libraries: a third of the memory). `dream agent ...` replaces itself
/// with `dream-agent ...`, found next to `dream`. Returns only on failure.
int ExecAgentBinary(int argc, char** argv);

/// What run, sim and launch are asked (and sweep of its base config).
using RunArgs = workflows::RunOptions;

struct AgentArgs {
  std::string config_path;
  std::string robots = "all";  ///< "all", "3", "0,2,5" or "0-4"
  std::string lcm_url;
  double idle_timeout_s = 60.0;
  long long seed = -1;  ///< as RunArgs: the world's --seed/--set, so agents build the same robots
  std::vector<std::string> sets;
  std::string report_path;  ///< --report: where to write what the agents refused (JSON), for dream launch
};

// Each command's file declares its subcommands on the dream command line
// (options, checks and the action that runs them); main() calls these in the
// order `dream --help` lists the subcommands.
void DeclareRunCommand(CommandLine& line);      ///< dream run (run_command.cc)
void DeclareSimCommand(CommandLine& line);      ///< dream sim (run_command.cc)
void DeclareAgentCommand(CommandLine& line);    ///< dream agent (agent_command.cc)
void DeclareLaunchCommand(CommandLine& line);   ///< dream launch (launch_command.cc)
void DeclareSpyCommand(CommandLine& line);      ///< dream spy (spy_command.cc)
void DeclareReplayCommand(CommandLine& line);   ///< dream replay (replay_command.cc)
void DeclareLogCommand(CommandLine& line);      ///< dream log info / diff / echo (log_command.cc)
void DeclareVersionCommand(CommandLine& line);  ///< dream version (version_command.cc)
void DeclareViewCommand(CommandLine& line);     ///< dream view (view_command.cc)

/// "dream 0.1.0 (git 7de8cc9a1b2c)": the version dream --version and dream
/// version print; without the commit when the build was not configured from git.
std::string VersionLine();

int RunEmbedded(const RunArgs& args);
int RunSimOnly(const RunArgs& args);
/// `hand_over_plugins`, when given, is called instead of loading the plugins
/// a config names (dream-agent, which holds its own copy of the dream
/// libraries, execs dream-agent-shared with the same words); it does not return.
int RunAgents(const AgentArgs& args, const std::function<void()>& hand_over_plugins = nullptr);
int RunLaunch(const RunArgs& args);
int RunLogInfo(const std::string& path);
/// Compares the payloads of each channel matching `channel_regex`, in order
/// (timestamps ignored). Exit 0 when equal.
int RunLogDiff(const std::string& a, const std::string& b, const std::string& channel_regex, bool raw = false);
/// Prints each decoded DREAM_* message on channels matching `channel_regex`
/// as one JSON object per line (at most `limit` when > 0).
int RunLogEcho(const std::string& path, const std::string& channel_regex, long long limit);
int RunSpy(const std::string& log_path, const std::string& lcm_url, bool print_command_only);

struct ReplayArgs {
  std::string run;        ///< a run folder (its run.lcmlog) or an .lcmlog file
  std::string lcm_url;    ///< empty: $LCM_DEFAULT_URL, else LCM's default
  bool paused = false;    ///< start paused
  bool with_spy = false;  ///< also open lcm-spy on the same URL
  bool print_command_only = false;
};
/// Plays a run log through LCM's log player GUI (lcm.logging.LogPlayer:
/// seek, pause, step, speed), started with java directly as dream spy starts
/// lcm-spy (Debian's lcm-logplayer-gui script passes -Xincgc, which Java 17
/// refuses). Exit 0, 1 for a missing or unreadable log.
int RunReplay(const ReplayArgs& args);

// --- the bridge to the Robotarium (bridge_commands.cc, docs/robotarium.md) ---

/// dream export, import, lab-replay, compare and check-submission, in that order.
void DeclareBridgeCommands(CommandLine& line);
/// dream calibrate (calibrate_command.cc, docs/calibration.md).
void DeclareCalibrateCommand(CommandLine& line);

// --- sweeps (sweep_command.cc, docs/sweeps.md) ---

struct SweepArgs {
  std::string config_path;
  std::string seeds;                       ///< "1-20", "7", "1,4,9-12"; empty: the config's seed
  std::vector<std::string> sets;           ///< "KEY=V1,V2,..." each
  std::vector<std::string> zips;           ///< --zip "KEY=V1,V2,..." each
  int jobs = 0;                            ///< runs at once; 0: one per core
  long long steps = 0;                     ///< 0: the config's step limit
  std::string out_dir;                     ///< empty: sweeps/<name> (or _2, ... when that holds a sweep)
  double run_timeout_s = 1800.0;           ///< a run still going after this is stopped and counts as failed
  std::string engine = "local";            ///< local, slurm or plan
  std::vector<std::string> slurm_options;  ///< passed on to sbatch
};

/// Runs the config over every seed x --set combination, `jobs` `dream run`
/// processes at a time (or as a Slurm job array, or only planned), and
/// writes <out>/runs/<run>/, sweep.csv and sweep.md (workflows::SweepWorkflow).
/// Exit 0 when every run ran (successful or not) or was submitted/planned, 4
/// when one failed to run, 1 for bad input (nothing is started), 130 when
/// interrupted. `dream sweep status|resume|table DIR` are its subcommands.
int RunSweep(const SweepArgs& args);
void DeclareSweepCommand(CommandLine& line);

// --- pictures and videos (render_command.cc, docs/rendering.md) ---

/// Draws a recorded run (workflows::RenderWorkflow): the arena picture
/// (.png/.svg), a video (.mp4/.gif, through ffmpeg) or its metrics over time
/// (--plot). Exit 0, 1 for bad input (nothing written), 2 usage, 130 interrupted.
void DeclareRenderCommand(CommandLine& line);

/// Parses "all", "3", "0,2,5", "0-4" into sorted unique ids < num_robots.
/// @throws std::invalid_argument naming the bad part.
std::vector<int> ParseRobotList(const std::string& text, int num_robots);

}  // namespace dream::cli
