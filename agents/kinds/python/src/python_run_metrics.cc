#include "dream/python/python_run_metrics.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "dream/files/file_text.h"

extern char** environ;

namespace dream::python {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxOutputBytes = 64ull << 20;  // a per-step series of 128 robots is far less

/// The temporary files of one computation, removed however it ends.
struct TempFiles {
  TempFiles() {
    char pattern[] = "/tmp/dream-run-metrics-XXXXXX";
    if (::mkdtemp(pattern) == nullptr) throw std::runtime_error("cannot make a temporary folder in /tmp");
    dir = pattern;
  }
  ~TempFiles() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  TempFiles(const TempFiles&) = delete;
  TempFiles& operator=(const TempFiles&) = delete;
  fs::path dir;
};

void WriteInput(const fs::path& path, const std::string& spec_json, const kind_api::RunPoses& poses) {
  if (poses.steps.empty()) throw std::runtime_error("the run's log has no DREAM_POSES");
  const size_t robots = poses.steps.front().poses.size();
  std::ofstream out(path, std::ios::binary);
  out << nlohmann::json{{"spec_bytes", spec_json.size()}, {"steps", poses.steps.size()}, {"robots", robots}}.dump()
      << "\n"
      << spec_json;
  for (const kind_api::RunPoses::Step& step : poses.steps)
    out.write(reinterpret_cast<const char*>(&step.step), sizeof(int64_t));
  for (const kind_api::RunPoses::Step& step : poses.steps) {
    if (step.poses.size() != robots) {
      throw std::runtime_error("step " + std::to_string(step.step) + " has " + std::to_string(step.poses.size()) +
                               " robots, the first " + std::to_string(robots));
    }
    for (const Eigen::Vector3d& robot : step.poses) {
      const double pose[3] = {robot.x(), robot.y(), robot.z()};
      out.write(reinterpret_cast<const char*>(pose), sizeof(pose));
    }
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// What the script wrote ("" when it wrote nothing there), bounded.
std::string ReadBounded(const fs::path& path) {
  std::error_code error;
  if (!fs::exists(path, error)) return "";
  return files::ReadFileText(path.string(), kMaxOutputBytes);
}

/// Runs python3 -I script [mode] input output with stderr to `errors`; its exit status, -1 when it
/// ran past `timeout_s`.
int RunPython(const std::string& script, const std::string& mode, const fs::path& input, const fs::path& output,
              const fs::path& errors, double timeout_s) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  // -B: no __pycache__ beside the user's module or in DREAM's install.
  std::vector<std::string> args = {DREAM_PYTHON3_EXECUTABLE, "-I", "-B", script};
  if (!mode.empty()) args.push_back(mode);
  args.push_back(input.string());
  args.push_back(output.string());
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawn_error = ::posix_spawn(&pid, DREAM_PYTHON3_EXECUTABLE, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0) {
    throw std::runtime_error(std::string("cannot start ") + DREAM_PYTHON3_EXECUTABLE +
                             " (Debian's python3 and python3-numpy)");
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

std::string ScriptIn(const std::string& runtime_dir) {
  const std::string script = (fs::path(runtime_dir) / "dream" / "run_metrics.py").string();
  if (!fs::is_regular_file(script)) {
    throw std::runtime_error(script + ": missing; it computes a Python controller's own metrics, goal and goal points");
  }
  return script;
}

/// Runs the script on the input in `temp` and reads its output document: `what` names the
/// class's functions in errors ("metrics()/goal()").
nlohmann::json RunScript(const std::string& script, const std::string& mode, const TempFiles& temp, double timeout_s,
                         const std::string& what) {
  const int status =
      RunPython(script, mode, temp.dir / "input", temp.dir / "output.json", temp.dir / "errors", timeout_s);
  if (status == -1) {
    throw std::runtime_error("the controller's " + what + " took more than " +
                             std::to_string(static_cast<int>(timeout_s)) + " s: stopped");
  }
  if (status != 0) {
    std::string errors = ReadBounded(temp.dir / "errors");
    while (!errors.empty() && (errors.back() == '\n' || errors.back() == '\r')) errors.pop_back();
    if (errors.size() > 2000) errors = "..." + errors.substr(errors.size() - 2000);
    throw std::runtime_error("the controller's " + what + ": " +
                             (errors.empty() ? "python3 exit " + std::to_string(status) : errors));
  }
  const nlohmann::json document = nlohmann::json::parse(ReadBounded(temp.dir / "output.json"), nullptr, false);
  if (!document.is_object()) throw std::runtime_error(script + " wrote no document for the controller's " + what);
  return document;
}

/// run_metrics.py's goal points, [[[x, y], ...] per robot], as points; anything else is the
/// script's fault, named.
std::vector<std::vector<Eigen::Vector2d>> PointsOf(const nlohmann::json& robots, const std::string& script) {
  std::vector<std::vector<Eigen::Vector2d>> points;
  for (const nlohmann::json& robot : robots) {
    if (!robot.is_array()) throw std::runtime_error(script + " wrote goal points that are not one list per robot");
    points.emplace_back();
    for (const nlohmann::json& point : robot) {
      if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) {
        throw std::runtime_error(script + " wrote a goal point that is not [x, y]: " + point.dump().substr(0, 80));
      }
      points.back().emplace_back(point[0].get<double>(), point[1].get<double>());
    }
  }
  return points;
}

}  // namespace

nlohmann::json PythonRunMetrics::Compute(const std::string& runtime_dir, const std::string& spec_json,
                                         const kind_api::RunPoses& poses) {
  const std::string script = ScriptIn(runtime_dir);
  TempFiles temp;
  WriteInput(temp.dir / "input", spec_json, poses);
  const nlohmann::json document = RunScript(script, "", temp, kTimeoutS, "metrics");
  if (!document.contains("metrics") || !document["metrics"].is_object()) {
    throw std::runtime_error(script + " wrote no metrics document");
  }
  return document;
}

std::vector<std::vector<Eigen::Vector2d>> PythonRunMetrics::GoalPoints(const std::string& runtime_dir,
                                                                       const std::string& spec_json, int num_robots) {
  const std::string script = ScriptIn(runtime_dir);
  TempFiles temp;
  {
    std::ofstream out(temp.dir / "input", std::ios::binary);
    out << nlohmann::json{{"spec_bytes", spec_json.size()}, {"robots", num_robots}}.dump() << "\n" << spec_json;
    if (!out.flush()) throw std::runtime_error("cannot write " + (temp.dir / "input").string());
  }
  const nlohmann::json document = RunScript(script, "--goal-points", temp, kGoalPointsTimeoutS, "goal_points()");
  if (!document.contains("goal_points") || !document["goal_points"].is_array()) {
    throw std::runtime_error(script + " wrote no goal points");
  }
  return PointsOf(document["goal_points"], script);
}

}  // namespace dream::python
