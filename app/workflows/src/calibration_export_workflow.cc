#include "dream/workflows/calibration_export_workflow.h"

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/config/config_node.h"

#include "dream/workflows/calibration_config.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/session/run_session.h"
#include "dream/files/run_folder_choice.h"
#include "dream/session/run_exit_code.h"
#include "dream/world/run_verdict.h"

namespace dream::workflows {

namespace fs = std::filesystem;

CalibrationExportWorkflow::Result CalibrationExportWorkflow::Export(const Options& given) const {
  Options args = given;
  bridge::ExportOptions& options = args.export_options;
  if (args.robots < CalibrationConfig::kMinRobots || args.robots > CalibrationConfig::kMaxRobots) {
    throw std::runtime_error("--robots " + std::to_string(args.robots) + ": the calibration drive runs " +
                             std::to_string(CalibrationConfig::kMinRobots) + " to " +
                             std::to_string(CalibrationConfig::kMaxRobots) + " robots (the lab's limit is 20)" +
                             (args.robots == 0 ? "; pass --robots N with --calibration" : ""));
  }
  options.strategy = bridge::Strategy::kReplay;
  options.calibration = true;
  const std::string name = CalibrationConfig::Name(args.robots);
  const std::string config_text = CalibrationConfig::Text(args.robots);
  // Both folders are checked before the run, so a refusal wastes none.
  const std::string out_dir = args.out_dir.empty() ? (fs::path("exports") / name).string() : args.out_dir;
  if (files::RunFolderChoice::HoldsRun(out_dir)) {
    throw std::runtime_error("--out " + out_dir +
                             " holds a run (run.lcmlog or summary.json); an export would "
                             "replace its config.yaml: choose another --out");
  }
  if (!args.run_dir.empty() && files::RunFolderChoice::HoldsRun(args.run_dir)) {
    throw std::runtime_error(args.run_dir + ": already holds a run (run.lcmlog or summary.json); --calibration " +
                             "writes a new one: name another folder, or leave it out (runs/" + name + ")");
  }
  if (!args.run_dir.empty() &&
      fs::weakly_canonical(fs::absolute(args.run_dir)) == fs::weakly_canonical(fs::absolute(out_dir))) {
    throw std::runtime_error(args.run_dir + " is also --out: the run and its export need folders of their own");
  }
  run_config::RunConfig config = run_config::LoadRunConfig(config::ConfigNode::LoadString(config_text, name + ".yaml"));
  session::RunSession::Options session_options;
  session_options.stop = args.stop;
  session::RunSession run(std::move(config), session_options);
  run.CheckAgents();
  const std::string run_dir = files::RunFolderChoice(args.run_dir, "runs/" + name, false).dir();
  lcm::LcmBus bus("memq://");
  Result done;
  done.run_dir = run_dir;
  const session::RunResult result = run.RunWithAgents(bus, {run_dir, config_text});
  done.exit_code = session::ExitCodeOf(result);
  const bool clean = result.judgement.verdict() == world::RunVerdict::kClean;
  // Clean, not merely accepted: the lab must run the program as it is.
  if (done.exit_code == session::kExitInterrupted) return done;
  if (done.exit_code != session::kExitOk || !clean) {
    *err_ << "dream export: the calibration run in " << run_dir << " is not clean (see above); nothing was "
          << "exported.\n";
    if (done.exit_code == session::kExitOk) done.exit_code = session::kExitNotReady;
    return done;
  }
  std::error_code error;
  if (args.out_dir.empty()) fs::create_directories("exports", error);
  try {
    done.exported = bridge::ExportSubmission(run_dir, out_dir, options);
    *out_ << "\n"
          << done.exported->instructions << "\nwritten: " << done.exported->out_dir << "/UPLOAD.txt, "
          << done.exported->upload_dir << "/ (" << done.exported->uploads.size()
          << " files); the simulated run: " << run_dir << "\n";
  } catch (const bridge::ExportRefused& refused) {
    *err_ << "dream export: " << refused.what() << "\nnothing was exported (the run is in " << run_dir << ").\n";
    done.exit_code = session::kExitRejected;
  }
  return done;
}

}  // namespace dream::workflows
