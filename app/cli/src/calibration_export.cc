// dream export --calibration: the calibration drive run and exported (docs/calibration.md).
#include "calibration_export.h"
#include "dream/session/run_exit_code.h"

#include <filesystem>
#include <iostream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/bridge/calibration_config.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/session/run_session.h"
#include "dream/hosting/hosted_agents.h"
#include "dream/files/run_folder_choice.h"
#include "run_output.h"

namespace dream::cli {

namespace fs = std::filesystem;

int RunCalibrationExport(const ExportArgs& args, bridge::ExportOptions options) {
  if (args.robots < bridge::CalibrationConfig::kMinRobots || args.robots > bridge::CalibrationConfig::kMaxRobots) {
    throw std::runtime_error("--robots " + std::to_string(args.robots) + ": the calibration drive runs " +
                             std::to_string(bridge::CalibrationConfig::kMinRobots) + " to " +
                             std::to_string(bridge::CalibrationConfig::kMaxRobots) +
                             " robots (the lab's limit is 20)" +
                             (args.robots == 0 ? "; pass --robots N with --calibration" : ""));
  }
  if (!args.config_path.empty()) {
    throw std::runtime_error("--config " + args.config_path + ": --calibration writes its own config; leave --config out");
  }
  if (!args.strategy.empty() && args.strategy != bridge::StrategyName(bridge::Strategy::kReplay)) {
    throw std::runtime_error("--strategy " + args.strategy + ": --calibration exports the program's commands open "
                             "loop (replay), which is what calibrate fits; leave --strategy out");
  }
  if (args.barriers) {
    throw std::runtime_error("--barriers: would change the program's commands where robots come close; "
                             "--calibration sends them unchanged (its robots never come close)");
  }
  options.strategy = bridge::Strategy::kReplay;
  options.calibration = true;
  const std::string name = bridge::CalibrationConfig::Name(args.robots);
  const std::string config_text = bridge::CalibrationConfig::Text(args.robots);
  // Both folders are checked before the run, so a refusal wastes none.
  const std::string out_dir = args.out_dir.empty() ? (fs::path("exports") / name).string() : args.out_dir;
  if (files::RunFolderChoice::HoldsRun(out_dir)) {
    throw std::runtime_error("--out " + out_dir + " holds a run (run.lcmlog or summary.json); an export would "
                             "replace its config.yaml: choose another --out");
  }
  if (!args.run_dir.empty() && files::RunFolderChoice::HoldsRun(args.run_dir)) {
    throw std::runtime_error(args.run_dir + ": already holds a run (run.lcmlog or summary.json); --calibration " +
                             "writes a new one: name another folder, or leave it out (runs/" + name + ")");
  }
  if (!args.run_dir.empty() && fs::weakly_canonical(fs::absolute(args.run_dir)) == fs::weakly_canonical(fs::absolute(out_dir))) {
    throw std::runtime_error(args.run_dir + " is also --out: the run and its export need folders of their own");
  }
  run_config::RunConfig config = run_config::LoadRunConfig(config::ConfigNode::LoadString(config_text, name + ".yaml"));
  session::RunSession::Options session_options;
  session_options.stop = &StopFlag();
  session::RunSession run(std::move(config), session_options);
  hosting::HostedAgents::Check(run.config(), run.factory(), 0.0, StopFlag());
  const std::string run_dir = files::RunFolderChoice(args.run_dir, "runs/" + name, false).dir();
  lcm::LcmBus bus("memq://");
  std::vector<int> ids(static_cast<size_t>(run.config().num_robots));
  std::iota(ids.begin(), ids.end(), 0);
  int run_code = kExitOk;
  bool clean = false;
  {
    const hosting::HostedAgents agents(bus, run.config(), ids, run.factory(),
                              {run.config().sim.agent_timeout_s, run.config().sim.start_timeout_s, 0.0});
    const session::RunResult result = run.Run(bus, {run_dir, config_text});
    run_code = session::ExitCodeOf(result);
    clean = result.judgement.verdict() == world::RunVerdict::kClean;
  }
  // Clean, not merely accepted: the lab must run the program as it is.
  if (run_code == kExitInterrupted) return run_code;
  if (run_code != kExitOk || !clean) {
    std::cerr << "dream export: the calibration run in " << run_dir << " is not clean (see above); nothing was "
              << "exported.\n";
    return run_code != kExitOk ? run_code : kExitNotReady;
  }
  std::error_code error;
  if (args.out_dir.empty()) fs::create_directories("exports", error);
  try {
    const bridge::ExportSummary summary = bridge::ExportSubmission(run_dir, out_dir, options);
    std::cout << "\n" << summary.instructions << "\nwritten: " << summary.out_dir << "/UPLOAD.txt, "
              << summary.upload_dir << "/ (" << summary.uploads.size() << " files); the simulated run: " << run_dir
              << "\n";
    return kExitOk;
  } catch (const bridge::ExportRefused& refused) {
    std::cerr << "dream export: " << refused.what() << "\nnothing was exported (the run is in " << run_dir << ").\n";
    return kExitRejected;
  }
}


}  // namespace dream::cli
