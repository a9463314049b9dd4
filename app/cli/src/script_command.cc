// dream run SCRIPT.py: an unmodified Robotarium script against DREAM's world
// (docs/robotarium-scripts.md). This file starts the script and watches it;
// workflows::ScriptRunWorkflow builds and runs the world.
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "commands.h"
#include "dream/files/run_folder_choice.h"
#include "dream/process/data_files.h"
#include "dream/process/process_group.h"
#include "dream/session/exit_code.h"
#include "dream/session/run_exit_code.h"
#include "dream/workflows/run_workflow.h"
#include "dream/workflows/script_run_workflow.h"
#include "dream/config/config_node.h"
#include "script_command.h"

namespace dream::cli {

namespace fs = std::filesystem;

namespace {

/// The script's hello line, or "" when it ended (or Ctrl-C came) before it
/// made its Robotarium. Bounded by ScriptRunWorkflow::kMaxHelloBytes.
std::string ReadHello(int fd) {
  std::string line;
  char buffer[4096];
  while (line.find('\n') == std::string::npos) {
    if (StopFlag().load()) return "";
    pollfd wait{fd, POLLIN, 0};
    if (::poll(&wait, 1, 200) <= 0) continue;
    const ssize_t got = ::read(fd, buffer, sizeof(buffer));
    if (got <= 0) return "";
    line.append(buffer, static_cast<size_t>(got));
    if (line.size() > workflows::ScriptRunWorkflow::kMaxHelloBytes) {
      throw std::runtime_error("the script's Robotarium(...) said more than " +
                               std::to_string(workflows::ScriptRunWorkflow::kMaxHelloBytes) + " bytes");
    }
  }
  return line.substr(0, line.find('\n'));
}

/// The script's environment: DREAM's rps first, where the run's files go, the bus.
std::vector<std::string> ScriptEnvironment(const std::string& run_dir, const std::string& url, long long seed,
                                           int hello_fd, int terminal_fd) {
  const std::string rps_dir = (fs::path(process::DataFiles::PythonRuntimeDir()) / "rps_dream").string();
  const char* old_path = std::getenv("PYTHONPATH");
  return {"PYTHONPATH=" + rps_dir + (old_path != nullptr && *old_path != '\0' ? ":" + std::string(old_path) : ""),
          "DREAM_RUN_DIR=" + run_dir,
          "DREAM_LCM_URL=" + url,
          "DREAM_SCRIPT_SEED=" + std::to_string(seed),
          "DREAM_SCRIPT_FD=" + std::to_string(hello_fd),
          "DREAM_SCRIPT_TERMINAL_FD=" + std::to_string(terminal_fd),
          "DREAM_PYTHON_TYPES_DIR=" + process::DataFiles::PythonTypesDir(),
          "DREAM_BRIDGE_PYTHON_DIR=" + process::DataFiles::BridgePythonDir()};
}

/// Ends the world once the script has ended, after a grace in which the world
/// ends the run by itself: the script told it every robot is done, or (when it
/// failed) that every robot's controller failed. A script killed before it
/// said either leaves the run to this stop.
class ScriptWatch {
 public:
  ScriptWatch(process::ProcessGroup& children, pid_t pid) : children_(children), pid_(pid) {
    thread_ = std::thread([this] { Watch(); });
  }
  ~ScriptWatch() { Join(); }
  const std::atomic<bool>& stop() const { return stop_; }
  void Join() {
    run_over_ = true;
    if (thread_.joinable()) thread_.join();
  }
  /// The script's exit code, -1 while it runs.
  int exit_code() const { return exit_code_; }

 private:
  void Watch() {
    using Clock = std::chrono::steady_clock;
    Clock::time_point ended{};
    while (!run_over_) {
      if (StopFlag().load()) stop_ = true;
      if (exit_code_ < 0) {
        exit_code_ = children_.TryWait(pid_);
        if (exit_code_ >= 0) ended = Clock::now();
      }
      if (exit_code_ >= 0 && Clock::now() - ended > std::chrono::seconds(10)) stop_ = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }

  process::ProcessGroup& children_;
  const pid_t pid_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> run_over_{false};
  std::atomic<int> exit_code_{-1};
  std::thread thread_;
};

int ScriptEndedEarly(int code, const std::string& run_dir) {
  if (StopFlag().load()) return session::kExitInterrupted;
  std::cout << "dream run: the script ended (exit code " << code
            << ") before it made its Robotarium: nothing was run; its output is in "
            << (fs::path(run_dir) / "script_output.txt").string() << std::endl;
  return session::kExitRunFailed;
}

}  // namespace

bool IsScriptPath(const std::string& path) { return fs::path(path).extension() == ".py"; }

std::string ScriptOfConfig(const std::string& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return "";
  const config::ConfigNode root = config::ConfigNode::LoadFile(path);
  if (!root.IsMap()) return "";
  const config::ConfigNode node = root.Optional("script");
  if (!node.IsDefined()) return "";
  fs::path script(node.AsString());
  if (script.is_relative()) script = fs::absolute(path).parent_path() / script;
  return script.lexically_normal().string();
}

namespace {

/// The run's options from the command line: of the script given, or of a
/// config naming one (its seed and name, --seed and --set applied).
workflows::ScriptRunWorkflow::Options ScriptOptions(const RunArgs& args, std::string* run_name) {
  workflows::ScriptRunWorkflow::Options options;
  options.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  options.session.python_runtime_dir = options.python_runtime_dir;
  options.sets = args.sets;
  options.steps = args.steps;
  options.watch = args;
  options.interrupted = &StopFlag();
  std::error_code error;
  if (IsScriptPath(args.config_path)) {
    if (!fs::is_regular_file(args.config_path, error)) {
      throw std::invalid_argument(args.config_path + ": no such script (a Python file)");  // main adds "dream: "
    }
    options.script_path = args.config_path;
    options.seed = args.seed >= 0 ? args.seed : 1;
    *run_name = workflows::ScriptRunWorkflow::RunName(args.config_path);
    return options;
  }
  // Checked now, --set and all, before the script starts.
  const auto base = workflows::RunWorkflow(options.python_runtime_dir, StopFlag()).LoadConfig(args);
  options.script_path = ScriptOfConfig(args.config_path);
  if (!fs::is_regular_file(options.script_path, error)) {
    throw std::invalid_argument(args.config_path + ": script: " + options.script_path +
                                ": no such script (a Python file)");
  }
  options.base_config_path = args.config_path;
  options.seed = static_cast<long long>(base.seed);
  *run_name = base.name;
  return options;
}

}  // namespace

int RunScript(const RunArgs& args, const std::vector<std::string>& script_args) {
  if (args.private_bus && !args.lcm_url.empty()) {
    throw std::invalid_argument("--private-bus and --lcm-url both choose the bus; give one");
  }
  std::string run_name;
  workflows::ScriptRunWorkflow::Options options = ScriptOptions(args, &run_name);
  const std::string url = workflows::ScriptRunWorkflow::BusUrl(args.lcm_url, args.private_bus);
  const std::string dir = fs::absolute(files::RunFolderChoice(args.out_dir, "runs/" + run_name, args.overwrite).dir())
                              .lexically_normal()
                              .string();
  int hello[2];
  if (::pipe2(hello, O_CLOEXEC) != 0) throw std::runtime_error("cannot make a pipe for the script");
  const int terminal = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  process::ProcessGroup children;
  const char* python = std::getenv("DREAM_PYTHON");
  std::vector<std::string> argv{python != nullptr && *python != '\0' ? python : "python3",
                                (fs::path(options.python_runtime_dir) / "rps_dream" / "run_script.py").string(),
                                fs::absolute(options.script_path).string()};
  argv.insert(argv.end(), script_args.begin(), script_args.end());
  const pid_t pid = children.Start(argv, (fs::path(dir) / "script_output.txt").string(),
                                   ScriptEnvironment(dir, url, options.seed, hello[1], terminal), {hello[1], terminal});
  ::close(hello[1]);
  if (terminal >= 0) ::close(terminal);
  const std::string line = ReadHello(hello[0]);
  ::close(hello[0]);
  if (line.empty()) return ScriptEndedEarly(children.WaitPassingOnStop(pid, StopFlag(), SIGTERM), dir);
  const workflows::ScriptRunWorkflow::Hello said = workflows::ScriptRunWorkflow::ParseHello(line);
  ScriptWatch watch(children, pid);
  options.session.stop = &watch.stop();
  const session::RunResult result = workflows::ScriptRunWorkflow(options).Run(said, dir, url);
  watch.Join();
  const int script_code =
      watch.exit_code() >= 0 ? watch.exit_code() : children.WaitPassingOnStop(pid, StopFlag(), SIGTERM);
  if (script_code != 0 && !StopFlag().load()) {
    std::cout << "dream run: the script failed (exit code " << script_code << "); its output, the traceback "
              << "included, is in " << (fs::path(dir) / "script_output.txt").string() << std::endl;
    // Its robots' faults ended the run, judged as any run whose controller failed; a script that
    // ended with none said (killed) ended it by the watch: the run did not finish.
    if (result.outcome.robot_faults.empty()) return session::kExitRunFailed;
  }
  return session::ExitCodeOf(result);
}

int RunScriptLabReplay(workflows::LabReplayWorkflow::Options options) {
  const std::string config_path = (fs::path(options.lab_dir) / "config.yaml").string();
  const std::string script = ScriptOfConfig(config_path);
  std::error_code error;
  if (!fs::is_regular_file(script, error)) {
    throw std::invalid_argument(config_path + ": script: " + script + ": no such script (a Python file)");
  }
  const config::ConfigNode root = config::ConfigNode::LoadFile(config_path);
  const long long seed = root.Optional("seed").IsDefined() ? root.Required("seed").AsInt() : 1;
  const std::string name = root.Required("name").AsString();
  options.out_dir =
      fs::absolute(files::RunFolderChoice(options.out_dir, "runs/" + name + "_lab_replay", options.overwrite).dir())
          .lexically_normal()
          .string();
  options.overwrite = true;  // the folder just chosen, which the script writes into first
  options.lcm_url = workflows::ScriptRunWorkflow::BusUrl(options.lcm_url, options.lcm_url.empty());
  options.script_agent = true;
  int hello[2];
  if (::pipe2(hello, O_CLOEXEC) != 0) throw std::runtime_error("cannot make a pipe for the script");
  const int terminal = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  process::ProcessGroup children;
  const char* python = std::getenv("DREAM_PYTHON");
  const std::vector<std::string> argv{
      python != nullptr && *python != '\0' ? python : "python3",
      (fs::path(process::DataFiles::PythonRuntimeDir()) / "rps_dream" / "run_script.py").string(), script};
  const pid_t pid = children.Start(argv, (fs::path(options.out_dir) / "script_output.txt").string(),
                                   ScriptEnvironment(options.out_dir, options.lcm_url, seed, hello[1], terminal),
                                   {hello[1], terminal});
  ::close(hello[1]);
  if (terminal >= 0) ::close(terminal);
  const std::string line = ReadHello(hello[0]);
  ::close(hello[0]);
  if (line.empty()) return ScriptEndedEarly(children.WaitPassingOnStop(pid, StopFlag(), SIGTERM), options.out_dir);
  workflows::ScriptRunWorkflow::ParseHello(line);  // checked; the replay's poses are the lab's
  ScriptWatch watch(children, pid);
  options.stop = &watch.stop();
  const workflows::LabReplayWorkflow::Result result = workflows::LabReplayWorkflow().Replay(options);
  watch.Join();
  if (watch.exit_code() < 0) children.WaitPassingOnStop(pid, StopFlag(), SIGTERM);
  return result.exit_code;
}

}  // namespace dream::cli
