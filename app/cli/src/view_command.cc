#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "command_line.h"
#include "commands.h"
#include "dream/files/file_text.h"
#include "dream/run_config/run_config.h"
#include "dream/session/experiment_goal.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/run_log/run_log.h"
#include "dream/view/frame_json.h"
#include "dream/view/live_view.h"
#include "dream/view/replay_json.h"
#include "dream/view/thread_priority.h"
#include "dream/view/view_server.h"
#include "run_view.h"
#include "shared_options.h"

namespace dream::cli {
namespace {

namespace fs = std::filesystem;

struct ViewArgs {
  std::string run;          ///< a run folder or .lcmlog to replay; empty: live from the bus
  std::string lcm_url;      ///< live: empty: $LCM_DEFAULT_URL, else LCM's default
  std::string config_path;  ///< goals, sensors and radio of the run; replay: config.yaml beside the log
  int port = 8077;
  std::string bind = "127.0.0.1";
  int fps = 0;  ///< live: frames a second to each page at most; 0: FrameRates' defaults (30, fewer while the run is fast)
};

/// The run's config: --config, else (replay) config.yaml beside the log. One
/// that cannot be read or is another run's is an error when given, a
/// warning when found beside the log.
std::optional<run_config::RunConfig> ConfigOfRun(const ViewArgs& args, const std::string& log_path, int log_robots) {
  std::string path = args.config_path;
  if (path.empty() && !log_path.empty()) {
    const fs::path beside = fs::path(log_path).parent_path() / "config.yaml";
    if (!fs::is_regular_file(beside)) return std::nullopt;
    path = beside.string();
  }
  if (path.empty()) return std::nullopt;
  try {
    run_config::RunConfig config = run_config::LoadRunConfigFile(path);
    if (log_robots > 0 && config.num_robots != log_robots) {
      throw std::runtime_error(path + " has " + std::to_string(config.num_robots) + " robots, " + log_path + " " +
                               std::to_string(log_robots) + ": not this run's config");
    }
    return config;
  } catch (const std::exception& e) {
    if (!args.config_path.empty()) throw;
    spdlog::warn("dream view: drawing without the config's goals and radio: {}", e.what());
    return std::nullopt;
  }
}

void WaitForCtrlC() {
  while (!StopFlag().load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

int RunLiveView(const ViewArgs& args) {
  const std::string url = lcm::ResolveLcmUrl(args.lcm_url);
  view::ViewSetup setup;
  if (const std::optional<run_config::RunConfig> config = ConfigOfRun(args, "", 0)) {
    setup = ViewSetupOfConfig(*config, view::ViewSetup::Mode::kLive, url);
  }
  setup.mode = view::ViewSetup::Mode::kLive;
  setup.source = url;
  if (args.fps > 0) setup.frame_rates = view::FrameRates::One(args.fps);
  // Best effort: the runs it watches (on this machine, often) get the cores first.
  view::LowerThisProcesssPriority();
  lcm::LcmBus bus(url);
  view::ViewServer server({args.bind, args.port, false, 8});
  view::LiveView live(bus, server, setup);
  std::cout << "dream view: open " << server.url() << " (live: any DREAM run on " << url << "); Ctrl-C to stop"
            << std::endl;
  while (!StopFlag().load()) bus.HandleSubscriptions(100);
  if (live.collector().bad_messages() > 0) {
    spdlog::warn("dream view: {} messages on DREAM_* channels did not decode and were not drawn",
                 live.collector().bad_messages());
  }
  return kExitOk;
}

/// The run's judgement from summary.json beside its log: what the page shows
/// as the verdict at the run's end (none without a readable summary).
std::optional<view::ViewSetup::Judged> JudgedOfRun(const std::string& log_path) {
  const std::string summary_path = (fs::path(log_path).parent_path() / "summary.json").string();
  std::error_code error;
  if (!fs::exists(summary_path, error)) return std::nullopt;
  try {
    const nlohmann::json summary = nlohmann::json::parse(files::ReadFileText(summary_path));
    view::ViewSetup::Judged judged;
    judged.verdict = summary.value("verdict", std::string());
    if (judged.verdict.empty()) return std::nullopt;
    for (const nlohmann::json& reason : summary.value("verdict_reasons", nlohmann::json::array())) {
      if (reason.is_object()) judged.reasons.push_back(reason.value("rule", "?") + ": " + reason.value("problem", ""));
    }
    judged.goal = session::ExperimentGoal::Text(summary.value("goal", nlohmann::json::object()));
    return judged;
  } catch (const std::exception& e) {
    spdlog::warn("{}: not read, the page shows the verdict of the counts only: {}", summary_path, e.what());
    return std::nullopt;
  }
}

int RunReplayView(const ViewArgs& args) {
  const std::string log_path = RunLogPath(args.run);
  const run_log::RunLog log = run_log::RunLog::Read(log_path);
  if (log.poses().empty()) {
    throw std::runtime_error(log_path + ": no DREAM_POSES that decode: nothing to replay" +
                             (log.Flaw(true) ? " (" + *log.Flaw(true) + ")" : std::string()));
  }
  view::ViewSetup setup;
  if (const std::optional<run_config::RunConfig> config = ConfigOfRun(args, log_path, log.num_robots())) {
    setup = ViewSetupOfConfig(*config, view::ViewSetup::Mode::kReplay, args.run, fs::absolute(log_path).parent_path().string());
  }
  setup.mode = view::ViewSetup::Mode::kReplay;
  setup.source = args.run;
  setup.judged = JudgedOfRun(log_path);
  view::ViewServer server({args.bind, args.port, true, 8});
  server.SetSetup(view::SetupJson(setup));
  server.SetRunData(view::RunReplayJson(log, setup));
  std::cout << "dream view: open " << server.url() << " (replay of " << args.run << ", " << log.poses().size()
            << " steps); Ctrl-C to stop" << std::endl;
  WaitForCtrlC();
  return kExitOk;
}

}  // namespace

void DeclareViewCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<ViewArgs>(
      "view",
      "Watch runs in a web browser: the arena to scale, robots, trails, goals, obstacles, radio,\n"
      "violations where and when they happen, the verdict so far. Served by dream on 127.0.0.1.\n"
      "Live (no RUN): draws any DREAM run on the LCM bus (dream sim, launch, lab-replay, lcm-logplayer).\n"
      "Replay: dream view runs/go_to_goal: the finished run with play, pause, step, scrub and speed.\n"
      "Example: dream view --config config/go_to_goal.yaml   (then open http://127.0.0.1:8077/)",
      std::function<int(const ViewArgs&)>([](const ViewArgs& a) { return a.run.empty() ? RunLiveView(a) : RunReplayView(a); }));
  command->add_option("run", args->run, "A run folder (its run.lcmlog) or an .lcmlog file to replay; none: live");
  command->add_option("--lcm-url", args->lcm_url,
                      "Live: LCM URL (default $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");
  command->add_option("--config", args->config_path,
                      "The run's config, for its goals, sensor ranges and radio links (replay: config.yaml\n"
                      "beside the log by default)");
  command->add_option("--port", args->port, "Port of the page (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command->add_option("--fps", args->fps,
                      "Live: frames a second each page gets and draws at most; fewer cost the machine less\n"
                      "(default: 30; 10 while the run goes faster than twice real time, 5 beyond ten times)")
      ->check(CLI::Range(1, view::FrameRates::kMax));
  command->add_option("--bind", args->bind,
                      "Address to listen on; 127.0.0.1 (the default) is this machine only,\n"
                      "0.0.0.0 exposes the page to the network on purpose")
      ->capture_default_str();
}

}  // namespace dream::cli
