#include "dream/session/run_session.h"
#include "dream/session/placed_start.h"
#include "dream/session/realism_notice.h"

#include <spdlog/spdlog.h>

#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

#include "dream/bridge/controller_module_copy.h"
#include "dream/bridge/pre_validation.h"
#include "dream/run_config/world_of_config.h"
#include "dream/files/atomic_file.h"
#include "dream/files/output_folder.h"
#include "dream/hosting/hosted_agents.h"
#include "dream/node/refused_record.h"
#include "dream/node/sim_node.h"
#include "dream/node/true_pose_recording.h"
#include "dream/session/run_exit_code.h"
#include "dream/session/terminal_progress.h"
#include "dream/session/verdict_broadcast.h"
#include "dream/world/barrier_world.h"
#include "dream/world/realistic_world.h"

namespace dream::session {
namespace {

constexpr const char* kLogName = RunReporter::kLogName;
constexpr const char* kRefusedLogName = "refused.lcmlog";

}  // namespace

// What the loop left for the report: the world (asked for its counts and
// final poses), how the run ended and what the world adds to summary.json.
struct RunSession::Stepped {
  std::unique_ptr<world::World> world;
  node::RunOutcome outcome;
  nlohmann::ordered_json world_fields = nlohmann::ordered_json::object();
  /// The run's folder was removed and made again while it ran (the log's
  /// .part there is another file): the folder is another run's now.
  bool folder_replaced = false;
};

bool RunSession::LogKeepsVerdict(const Stepped& stepped) {
  // A log the disk refused stays as the failure left it: every whole event before it.
  return !stepped.folder_replaced && stepped.outcome.end != node::RunOutcome::End::kFailed;
}

RunSession::RunSession(run_config::RunConfig config, Options options) : config_(std::move(config)), options_(options) {
  try {
    factory_ = std::make_unique<agent_host::ControllerFactory>(config_);
  } catch (const std::exception& e) {
    factory_error_ = e.what();
  }
}

RunSession::RunSession(run_config::RunConfig config) : RunSession(std::move(config), Options()) {}

RunSession::~RunSession() = default;

void RunSession::CheckAgents() const {
  static const std::atomic<bool> never{false};
  hosting::HostedAgents::Check(config_, factory_.get(), config_.sim.start_timeout_s,
                               options_.stop != nullptr ? *options_.stop : never);
}

RunResult RunSession::Run(lcm::LcmInterface& lcm, const Folder& folder) { return Run(lcm, folder, OwnWorld()); }

RunResult RunSession::RunWithAgents(lcm::LcmBus& bus, const Folder& folder) {
  return RunWithAgents(bus, folder, OwnWorld());
}

RunResult RunSession::RunWithAgents(lcm::LcmBus& bus, const Folder& folder, const GivenWorld& world) {
  std::unique_ptr<hosting::HostedAgents> agents;  // until the run is reported
  GivenWorld hosted = world;
  // The agents are started once, when every check of the run has passed (the
  // session's one run, its folder, the world made): a refused run starts
  // none. Hosted before the world's first step and until its last status:
  // they answer step 0.
  hosted.make = [&](node::RunRecorder& recorder) {
    std::unique_ptr<world::World> made = world.make(recorder);
    if (made == nullptr) return made;  // Step refuses it
    std::vector<int> ids(static_cast<size_t>(config_.num_robots));
    std::iota(ids.begin(), ids.end(), 0);
    agents = std::make_unique<hosting::HostedAgents>(
        bus, config_, ids, factory_.get(),
        python_host::PythonHostProcess::Limits{config_.sim.agent_timeout_s, config_.sim.start_timeout_s, 0.0});
    return made;
  };
  return Run(bus, folder, hosted);
}

RunSession::GivenWorld RunSession::OwnWorld() {
  // world.realism: the official world seen and driven as on the lab; off
  // (ideal), the official world itself, with nothing in between.
  GivenWorld own;
  own.make = [this](node::RunRecorder& recorder) {
    // world.start: placed: the lab's start-up drive first; step 0 is where it ended.
    if (config_.start == run_config::WorldStart::kPlaced) {
      return run_config::WorldOfConfig(PlacedStart::Drive(config_, recorder));
    }
    return run_config::WorldOfConfig(config_);
  };
  return own;
}

RunResult RunSession::Run(lcm::LcmInterface& lcm, const Folder& folder, const GivenWorld& world) {
  if (ran_) throw std::logic_error("RunSession::Run: a session runs once (" + config_.name + ")");
  ran_ = true;
  const Stepped stepped = Step(lcm, folder, world);
  RunResult result = Report(stepped, folder.dir);
  // After summary.json: a viewer ends on the one judge's verdict, and a log
  // written whole keeps it as its last event (summary.json's log_events counts it).
  if (result.summary_written) {
    const run_verdict_t verdict = VerdictBroadcast::MessageOf(result, stepped.outcome.run_id, stepped.world->utime(),
                                                              ExitCodeOf(result, /*log_failure=*/false));
    VerdictBroadcast::Send(lcm, verdict, LogKeepsVerdict(stepped) ? folder.dir + "/" + kLogName : std::string(),
                           stepped.outcome.log_events);
  }
  return result;
}

RunSession::Stepped RunSession::Step(lcm::LcmInterface& lcm, const Folder& folder, const GivenWorld& given) {
  // A copy of the config beside the log, so the run folder alone is enough
  // for `dream export` and `dream compare`, and to rerun it.
  files::WriteFileAtomically(folder.dir + "/config.yaml", folder.config_text);
  bridge::KeepControllerModule(config_, files::OutputFolder(folder.dir));
  bridge::KeepRealismFile(config_, files::OutputFolder(folder.dir));
  Stepped stepped;
  const std::string log_path = folder.dir + "/" + kLogName;
  {
    node::RunRecorder recorder(log_path);
    stepped.world = given.make(recorder);
    if (stepped.world == nullptr) throw std::logic_error("RunSession: the given world's make() returned none");
    // A realistic world's log keeps the truth on DREAM_POSES, the agents' view on DREAM_MEASURED_POSES.
    std::optional<node::TruePoseRecording> truth;
    if (const auto* realistic = dynamic_cast<const world::RealisticWorld*>(&world::SteppingWorldOf(*stepped.world))) {
      truth.emplace(recorder, *realistic);
    }
    // What the world refuses is kept apart from the run's log (at most a few MB).
    node::RefusedRecord refused(folder.dir + "/" + kRefusedLogName);
    node::SimNode node(lcm, *stepped.world, &recorder, config_.sim);
    node.set_refused_record(&refused);
    if (given.start_line.empty()) {
      spdlog::info("{}: {} robots, up to {} steps, {} on {}", config_.name, config_.num_robots, config_.sim.max_steps,
                   config::WorldModeName(config_.sim.mode), lcm.url());
    } else {
      spdlog::info("{}", given.start_line);
    }
    if (const std::string realism = RealismNotice(config_); !realism.empty()) spdlog::info("{}", realism);
    TerminalProgress progress(config_.sim.progress_interval_s);
    node.set_progress_reporter(progress.reporter());
    static const std::atomic<bool> never(false);
    stepped.outcome = node.Run(options_.stop != nullptr ? *options_.stop : never);
    try {
      recorder.Close();
    } catch (const std::exception& e) {
      // The node has flushed the log already, so this is rare (a rename that
      // fails); the summary still tells what the run did and why the log is short.
      stepped.outcome.end = node::RunOutcome::End::kFailed;
      stepped.outcome.reason = e.what();
    }
    stepped.outcome.log_events = recorder.events_written();
    stepped.folder_replaced = recorder.part_replaced();
  }
  if (given.summary_fields) stepped.world_fields = given.summary_fields(*stepped.world);
  return stepped;
}

RunReporter RunSession::Reporter() const {
  return RunReporter(config_, factory_.get(), factory_error_,
                     {options_.report, options_.steps_from_command_line, options_.quiet, options_.python_runtime_dir});
}

RunResult RunSession::Report(const Stepped& stepped, const std::string& dir) {
  if (stepped.folder_replaced) {
    // Its log, summary and picture there would be another run's, or pass for
    // them: nothing of this run is written over them.
    spdlog::error("{}: {}; no summary.json or picture written there either", dir, stepped.outcome.reason);
    *options_.report << "failed after " << stepped.outcome.steps << " steps: " << stepped.outcome.reason << "\n";
    RunResult result;
    result.outcome = stepped.outcome;
    return result;
  }
  RunReporter::Ended ended;
  ended.world = stepped.world.get();
  ended.outcome = stepped.outcome;
  if (LogKeepsVerdict(stepped)) ++ended.outcome.log_events;  // DREAM_VERDICT, appended once summary.json is written
  ended.dir = dir;
  ended.fields = stepped.world_fields;
  return Reporter().Report(ended);
}

}  // namespace dream::session
