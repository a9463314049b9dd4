#include "dream/workflows/script_run_workflow.h"

#include <atomic>
#include <cctype>
#include <memory>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/config_overrides/config_override.h"
#include "dream/config_overrides/config_text.h"
#include "dream/config_overrides/overridden_config.h"
#include "dream/files/atomic_file.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/run_config/run_config.h"
#include "dream/workflows/run_view.h"

namespace dream::workflows {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxScriptRobots = 50;  // the official Robotarium(...) refuses more

std::runtime_error HelloError(const std::string& what) {
  return std::runtime_error("the script's Robotarium(...) said something dream run cannot use: " + what);
}

std::array<double, 3> PoseOf(const nlohmann::json& pose, size_t index) {
  const std::string name = "initial_poses[" + std::to_string(index) + "]";
  if (!pose.is_array() || pose.size() != 3) throw HelloError(name + " is not [x, y, theta]: " + pose.dump());
  std::array<double, 3> values{};
  for (size_t k = 0; k < 3; ++k) {
    if (!pose[k].is_number() || !std::isfinite(pose[k].get<double>())) {
      throw HelloError(name + "[" + std::to_string(k) + "] is not a finite number: " + pose[k].dump());
    }
    values[k] = pose[k].get<double>();
  }
  return values;
}

std::string Exact(double value) {
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
  return text.str();
}

}  // namespace

bool ScriptRunWorkflow::IsScript(const std::string& path) { return fs::path(path).extension() == ".py"; }

run_config::RunConfig ScriptRunWorkflow::BaseConfig(const std::string& script_path,
                                                    const std::string& python_runtime_dir) {
  std::error_code error;
  if (!fs::is_regular_file(script_path, error)) {
    throw std::invalid_argument(script_path + ": no such script (a Python file)");
  }
  return run_config::LoadRunConfig(
      config::ConfigNode::LoadString(BaseConfigText(script_path, python_runtime_dir), script_path));
}

std::string ScriptRunWorkflow::RunName(const std::string& script_path) {
  std::string name = fs::path(script_path).stem().string();
  for (char& c : name) {
    const bool allowed = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
    if (!allowed) c = '_';
  }
  return name.empty() ? "script" : name;
}

ScriptRunWorkflow::Hello ScriptRunWorkflow::ParseHello(const std::string& line) {
  if (line.size() > kMaxHelloBytes) {
    throw HelloError("more than " + std::to_string(kMaxHelloBytes) + " bytes");
  }
  const nlohmann::json hello = nlohmann::json::parse(line, nullptr, false);
  if (hello.is_discarded() || !hello.is_object()) throw HelloError("not a JSON object: " + line.substr(0, 200));
  Hello result;
  const auto robots = hello.find("robots");
  if (robots == hello.end() || !robots->is_number_integer() || robots->get<long long>() < 1 ||
      robots->get<long long>() > kMaxScriptRobots) {
    throw HelloError("robots must be 1.." + std::to_string(kMaxScriptRobots) + ", got " +
                     (robots == hello.end() ? std::string("nothing") : robots->dump()));
  }
  result.robots = robots->get<int>();
  const auto poses = hello.find("initial_poses");
  if (poses == hello.end() || !poses->is_array() || poses->size() != static_cast<size_t>(result.robots)) {
    throw HelloError("initial_poses must hold one [x, y, theta] per robot (" + std::to_string(result.robots) + ")");
  }
  for (size_t i = 0; i < poses->size(); ++i) result.initial_poses.push_back(PoseOf((*poses)[i], i));
  const auto steps = hello.find("startup_steps");
  if (steps != hello.end()) {
    if (!steps->is_number_integer() || steps->get<long long>() < 0) {
      throw HelloError("startup_steps must be a whole number >= 0, got " + steps->dump());
    }
    result.startup_steps = steps->get<long long>();
  }
  return result;
}

std::string ScriptRunWorkflow::ConfigText(const Hello& hello, const Options& options, const std::string& goal_record) {
  const fs::path script = fs::absolute(options.script_path).lexically_normal();
  const fs::path placeholder = fs::path(options.python_runtime_dir) / "rps_dream" / "robotarium_script.py";
  std::ostringstream yaml;
  yaml << "# The run of a Robotarium script (dream run SCRIPT.py, docs/robotarium-scripts.md): its robots\n"
       << "# start where the official start-up drive left them (" << hello.startup_steps << " steps), and\n"
       << "# the script drives them all. Rerun it with: dream run " << script.string() << "\n"
       << "name: " << RunName(options.script_path) << "\n"
       << "description: " << nlohmann::json(std::string("Robotarium script ") + script.string()).dump() << "\n"
       << "script: " << nlohmann::json(script.string()).dump() << "\n"
       << "seed: " << options.seed << "\n"
       << "robots: " << hello.robots << "\n"
       << "steps: " << (options.steps > 0 ? options.steps : kDefaultSteps) << "\n"
       << "stop_when_done: true\n"
       << "world:\n  mode: lockstep\n  agent_timeout_s: 60.0\n  start_timeout_s: 120.0\n"
       << "  # the official simulator takes any finite command (and saturates the wheels): so does this run\n"
       << "  command_limits: official\n"
       << "  # the run's steps are the script's step() calls; the script's end (or its error) ends the run\n"
       << "  script_ends_run: true\n"
       << "initial_poses:\n";
  for (const auto& pose : hello.initial_poses) {
    yaml << "  - [" << Exact(pose[0]) << ", " << Exact(pose[1]) << ", " << Exact(pose[2]) << "]\n";
  }
  yaml << "controller:\n  kind: python\n  module: " << nlohmann::json(placeholder.string()).dump()
       << "\n  class: RobotariumScript\n";
  if (!goal_record.empty()) {
    yaml
        << "  # where the script's last at_pose/at_position check is written: the run's goal unless goal_points/poses\n"
        << "  goal_record: " << nlohmann::json(goal_record).dump() << "\n";
  }
  return yaml.str();
}

std::string ScriptRunWorkflow::BaseConfigText(const std::string& script_path, const std::string& python_runtime_dir) {
  Hello placeholder;
  placeholder.robots = 1;
  placeholder.initial_poses = {{0.0, 0.0, 0.0}};
  Options options;
  options.script_path = script_path;
  options.python_runtime_dir = python_runtime_dir;
  return "# robots and initial_poses: placeholders; each run takes them from the script's Robotarium(...)\n" +
         ConfigText(placeholder, options);
}

std::string ScriptRunWorkflow::WithHello(const std::string& base_path, const Hello& hello, const Options& options,
                                         const std::string& goal_record) {
  YAML::Node root = config::ConfigNode::ParseYaml(config::ConfigNode::ReadFile(base_path), base_path);
  std::string poses = "[";
  for (const auto& pose : hello.initial_poses) {
    poses += (poses.size() > 1 ? ", [" : "[") + Exact(pose[0]) + ", " + Exact(pose[1]) + ", " + Exact(pose[2]) + "]";
  }
  config_overrides::ApplyConfigOverride(root, "robots", std::to_string(hello.robots), base_path);
  config_overrides::ApplyConfigOverride(root, "initial_poses", poses + "]", base_path);
  config_overrides::ApplyConfigOverride(root, "seed", std::to_string(options.seed), base_path);
  if (options.steps > 0) config_overrides::ApplyConfigOverride(root, "steps", std::to_string(options.steps), base_path);
  if (!goal_record.empty()) {
    config_overrides::ApplyConfigOverride(root, "controller.goal_record", nlohmann::json(goal_record).dump(),
                                          base_path);
  }
  // A config written before the key: the script's run ends with its script (Run refuses false).
  if (!root["world"] || !root["world"]["script_ends_run"]) {
    config_overrides::ApplyConfigOverride(root, "world.script_ends_run", "true", base_path);
  }
  return config_overrides::ConfigText(root, "The run of a Robotarium script from " + base_path +
                                                ": robots and initial_poses as its\nRobotarium(...) said (" +
                                                std::to_string(hello.startup_steps) +
                                                " steps of the official start-up drive).");
}

session::RunResult ScriptRunWorkflow::Run(const Hello& hello, const std::string& run_dir,
                                          lcm::LcmInterface& lcm) const {
  const RunOptions& watch = options_.watch;
  const RunView::Keep keep = RunView::Keep::Parse(watch.view_keep);  // a bad value before anything runs
  const std::string config_path = (fs::path(run_dir) / "robotarium_script.yaml").string();
  // DREAM's rps removed an earlier run's record from the folder before its hello: the record is this run's.
  const fs::path goal_record = fs::path(run_dir) / kGoalRecordName;
  files::WriteFileAtomically(config_path,
                             options_.base_config_path.empty()
                                 ? ConfigText(hello, options_, goal_record.string())
                                 : WithHello(options_.base_config_path, hello, options_, goal_record.string()));
  const config_overrides::OverriddenConfig overridden(config_path, -1, options_.sets);
  run_config::RunConfig config = overridden.LoadWith(&run_config::LoadRunConfig);
  if (!config.sim.script_ends_run) {
    throw config::ConfigError(
        config_path +
        ": world.script_ends_run: false, but a script's run ends with its script (the run's steps "
        "are its step() calls): leave it true");
  }
  // As any run: paced only when asked (--pace), or watched (--view: real time unless --pace says otherwise).
  if (watch.pace >= 0.0) {
    config.sim.pace = watch.pace;
  } else if (watch.view) {
    config.sim.pace = 1.0;
  }
  session::RunSession session(std::move(config), options_.session);
  try {
    session.CheckAgents();  // the controller's keys (the goal's: controller.goal_points, ...) before the run
  } catch (const config::ConfigError& e) {
    throw config::ConfigError(overridden.Noted(e.what()));
  }
  const std::string text = run_config::RunFolderConfigText(session.config(), overridden.Text());
  static const std::atomic<bool> never{false};
  const std::atomic<bool>& stop = options_.interrupted != nullptr ? *options_.interrupted : never;
  std::unique_ptr<RunView> view;
  if (watch.view) {
    view = std::make_unique<RunView>(lcm, session.config(), watch.view_bind, watch.view_port, watch.view_fps,
                                     options_.python_runtime_dir, stop);
    // A refusal is Ctrl-C, which also sets the session's stop: the run ends interrupted at once.
    if (watch.view_wait) view->WaitForBrowser(watch.view_wait_timeout_s);
  }
  const session::RunResult result = session.Run(lcm, {run_dir, text});
  if (view) {
    view->ServeReplayOf(run_dir);
    view->KeepServing(keep);  // Ctrl-C here ends the serving, not the run: its exit code stands
  }
  return result;
}

session::RunResult ScriptRunWorkflow::Run(const Hello& hello, const std::string& run_dir,
                                          const std::string& url) const {
  lcm::LcmBus bus(url);
  return Run(hello, run_dir, bus);
}

std::string ScriptRunWorkflow::BusUrl(const std::string& lcm_url, bool private_bus) {
  return private_bus ? lcm::PrivateUdpmUrl() : lcm::ResolveLcmUrl(lcm_url);
}

}  // namespace dream::workflows
