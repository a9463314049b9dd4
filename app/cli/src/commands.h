#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dream/session/exit_code.h"

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

struct RunArgs {
  std::string config_path;
  std::string out_dir;            ///< empty: runs/<name>, or runs/<name>_2, ... when that holds a run
  bool overwrite = false;         ///< replace a run already in the output folder
  long long seed = -1;            ///< --seed; < 0: the config's
  std::vector<std::string> sets;  ///< --set KEY=VALUE each, applied in order
  std::string lcm_url;            ///< empty: memq:// for run, else LCM_DEFAULT_URL
  long long steps = 0;            ///< 0: the config's
  std::string mode;               ///< empty: the config's
  bool all_steps = false;         ///< run every step even when all robots report done
  double pace =
      -1.0;  ///< --pace: simulated seconds per wall second; 0: unpaced; < 0 (not given): unpaced, 1 with --view
  bool view = false;                    ///< dream run --view: serve the live arena (dream view) while it runs
  int view_port = 8077;                 ///< --view-port
  std::string view_bind = "127.0.0.1";  ///< --view-bind
  int view_fps = 0;        ///< --view-fps: frames a second to the page at most; 0: 30, or 10 while the run is fast
  bool view_wait = false;  ///< --view-wait: no step 0 before a browser has the page open
  double view_wait_timeout_s = 0.0;   ///< --view-wait-timeout: start anyway after this long; 0: wait until Ctrl-C
  std::string view_keep = "watched";  ///< --view-keep: how long the replay is served after the run (RunView::Keep)
};

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

struct ExportArgs {
  std::string run_dir;       ///< a folder written by dream run (--calibration: the run folder to write)
  std::string out_dir;       ///< empty: exports/<name>
  std::string config_path;   ///< empty: <run_dir>/config.yaml
  std::string strategy;      ///< empty: track (--calibration: replay)
  bool calibration = false;  ///< run the calibration drive on `robots` robots, then export it
  int robots = 0;            ///< --robots, with --calibration only; 0: not given
  bool barriers = false;
  int settle_steps = 240;
  bool force = false;  ///< export although robots were lost
};

struct ImportArgs {
  std::string result;  ///< dream_result.npy / .mat, or a folder holding one
  std::string export_dir;
  std::string out_dir;               ///< empty: runs/<name>_lab (or _2, ... when that holds a run)
  bool overwrite = false;            ///< replace a run already in the output folder
  int declared_robots = 0;           ///< declared on the lab's form; 0: the export's (UPLOAD.txt)
  double declared_duration_s = 0.0;  ///< declared on the lab's form; 0: the export's (UPLOAD.txt)
};

struct LabReplayArgs {
  std::string lab_dir;      ///< a folder written by dream import
  std::string out_dir;      ///< empty: runs/<name>_lab_replay (or _2, ... when that holds a run)
  bool overwrite = false;   ///< replace a run already in the output folder
  std::string lcm_url;      ///< empty: memq:// with in-process agents, else LCM_DEFAULT_URL
  long long steps = 0;      ///< 0: the whole lab run
  std::string mode;         ///< empty: the config's
  bool world_only = false;  ///< no in-process agents: they run elsewhere (dream agent)
};

struct CompareArgs {
  std::string first_dir;   ///< the simulated run
  std::string second_dir;  ///< the lab run
  std::string out_dir;     ///< empty: second_dir
};

struct CheckSubmissionArgs {
  std::string export_dir;
  std::string out_dir;    ///< empty: runs/<name>_check
  std::string run_dir;    ///< the simulated run to compare with; empty: the export's source run
  std::string simulator;  ///< a robotarium_python_simulator checkout; empty: $ROBOTARIUM_PYTHON_SIMULATOR
  std::string python;     ///< empty: the configured Python (/usr/bin/python3)
  bool standin = false;   ///< use the stand-in even when the official simulator is there
  bool require_official = false;
  bool skip_initialization = false;
  bool overwrite = false;  ///< replace a run (an earlier check) already in the output folder
};

int RunExport(const ExportArgs& args);
int RunImport(const ImportArgs& args);
int RunLabReplay(const LabReplayArgs& args);
int RunCompare(const CompareArgs& args);
int RunCheckSubmission(const CheckSubmissionArgs& args);
/// dream export, import, lab-replay, compare and check-submission, in that order.
void DeclareCalibrateCommand(CommandLine& line);
void DeclareBridgeCommands(CommandLine& line);

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

struct RenderArgs {
  std::string input;        ///< a run folder (its run.lcmlog) or an .lcmlog file
  std::string out;          ///< .png/.svg/.mp4/.gif; empty: beside the log (trajectories.svg, run.mp4, metrics.png)
  std::string config_path;  ///< empty: config.yaml beside the log, when there
  bool video = false;       ///< no --out: write run.mp4
  bool plot = false;        ///< metric plots instead of the arena
  std::vector<std::string> metrics;  ///< --metric NAME: plot only these series (implies plot)
  bool radio_links = false;
  bool sensor_ranges = false;
  int width_px = 0;       ///< 0: 1280 pictures, 1000 plots, 720 MP4, 480 GIF
  double fps = 0;         ///< 0: 30 MP4, 15 GIF
  double speed = 4.0;     ///< simulated seconds per video second
  double trail_s = 10.0;  ///< simulated seconds of trail behind each robot
};

/// Draws a recorded run: the arena picture (.png/.svg), a video (.mp4/.gif,
/// through ffmpeg) or its metrics over time (--plot). Exit 0, 1 for bad
/// input (nothing written), 2 usage, 130 interrupted.
int RunRender(const RenderArgs& args);
void DeclareRenderCommand(CommandLine& line);

/// Parses "all", "3", "0,2,5", "0-4" into sorted unique ids < num_robots.
/// @throws std::invalid_argument naming the bad part.
std::vector<int> ParseRobotList(const std::string& text, int num_robots);

}  // namespace dream::cli
