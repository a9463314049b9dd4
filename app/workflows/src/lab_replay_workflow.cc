#include "dream/workflows/lab_replay_workflow.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "dream/bridge/lab_replay_world.h"
#include "dream/bridge/run_track.h"
#include "dream/files/file_text.h"
#include "dream/files/run_folder_choice.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/run_config/run_config.h"
#include "dream/session/run_exit_code.h"
#include "dream/session/run_session.h"

namespace dream::workflows {

namespace fs = std::filesystem;

LabReplayWorkflow::Result LabReplayWorkflow::Replay(const Options& options) const {
  const std::string log_in = (fs::path(options.lab_dir) / "run.lcmlog").string();
  const std::string config_in = (fs::path(options.lab_dir) / "config.yaml").string();
  run_config::RunConfig config = run_config::LoadRunConfigFile(config_in);
  if (!config.script.empty() && !options.script_agent) {
    throw std::runtime_error(config_in + ": the lab run of a Robotarium script (" + config.script +
                             "): its agent is the script, which dream lab-replay starts itself (not with "
                             "--world-only: start no dream agent for it)");
  }
  bridge::RunTrack track = bridge::ReadRunTrack(log_in);
  if (track.num_robots != config.num_robots) {
    throw std::runtime_error(log_in + ": has " + std::to_string(track.num_robots) + " robots, " + config_in + " " +
                             std::to_string(config.num_robots));
  }
  if (track.last_step() < 1) throw std::runtime_error(log_in + ": the lab run has no step to replay");
  config.sim.max_steps = options.steps > 0 ? std::min<int64_t>(options.steps, track.last_step()) : track.last_step();
  config.sim.stop_when_done = false;  // the lab run is replayed to its end
  if (!options.mode.empty()) config.sim.mode = config::ParseWorldMode(options.mode);
  session::RunSession::Options session_options;
  session_options.steps_from_command_line = options.steps > 0;
  session_options.report = report_;
  session_options.stop = options.stop;
  session_options.python_runtime_dir = options.python_runtime_dir;
  session::RunSession run(std::move(config), session_options);
  run.CheckAgents();

  const std::string out_dir =
      files::RunFolderChoice(options.out_dir, "runs/" + run.config().name + "_lab_replay", options.overwrite).dir();
  const bool in_process = !options.world_only && !options.script_agent;
  lcm::LcmBus bus(options.lcm_url.empty() ? (in_process ? "memq://" : lcm::ResolveLcmUrl(""))
                                          : lcm::ResolveLcmUrl(options.lcm_url));

  // The lab's poses, replayed as the world; what it adds to the summary: the
  // agents' commands beside the lab's, how differently the controller reacts
  // to the real poses than the lab script drove.
  const bridge::LabReplayWorld* replay = nullptr;
  session::RunSession::GivenWorld world;
  world.make = [&](node::RunRecorder& recorder) {
    auto made = std::make_unique<bridge::LabReplayWorld>(std::move(track), run.config().world, &recorder);
    replay = made.get();
    return made;
  };
  Result result;
  world.summary_fields = [&](const world::World&) {
    result.agreement = bridge::CommandAgreement::Of(*replay);
    nlohmann::ordered_json fields;
    fields["config"] = "config.yaml";
    fields["lab_replay"] = {{"lab_run", fs::absolute(options.lab_dir).string()},
                            {"lab_command_channels", std::string(lcm::kLabCommandChannelPrefix) + "<id>"},
                            {"agents_vs_lab_commands", result.agreement->Json()}};
    return fields;
  };
  world.start_line = run.config().name + ": replaying " + std::to_string(run.config().sim.max_steps) +
                     " lab steps of " + std::to_string(run.config().num_robots) + " robots (" +
                     config::WorldModeName(run.config().sim.mode) + ") on " + bus.url() +
                     (in_process             ? " with the agents in this process"
                      : options.script_agent ? " with the script as every robot's agent"
                                             : "; start the agents with dream agent");
  // The same recording, summary, verdict, report and picture as every run.
  const session::RunSession::Folder folder{out_dir, files::ReadFileText(config_in)};
  result.exit_code =
      session::ExitCodeOf(in_process ? run.RunWithAgents(bus, folder, world) : run.Run(bus, folder, world));
  return result;
}

}  // namespace dream::workflows
