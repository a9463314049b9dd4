#include "dream/workflows/export_workflow.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "dream/bridge/export_options.h"
#include "dream/files/file_text.h"
#include "dream/run_config/run_config.h"
#include "dream/session/exit_code.h"
#include "dream/workflows/calibration_export_workflow.h"

namespace dream::workflows {

namespace fs = std::filesystem;

namespace {

/// export --calibration --robots N: the flags that do not go with it
/// refused, then the workflow (CalibrationExportWorkflow).
int ExportCalibration(const ExportWorkflow::Asked& asked, const bridge::ExportOptions& options) {
  if (!asked.config_path.empty()) {
    throw std::runtime_error("--config " + asked.config_path +
                             ": --calibration writes its own config; leave --config out");
  }
  if (!asked.strategy.empty() && asked.strategy != bridge::StrategyName(bridge::Strategy::kReplay)) {
    throw std::runtime_error("--strategy " + asked.strategy +
                             ": --calibration exports the program's commands open "
                             "loop (replay), which is what calibrate fits; leave --strategy out");
  }
  if (asked.barriers) {
    throw std::runtime_error(
        "--barriers: would change the program's commands where robots come close; "
        "--calibration sends them unchanged (its robots never come close)");
  }
  CalibrationExportWorkflow::Options calibration;
  calibration.robots = asked.robots;
  calibration.out_dir = asked.out_dir;
  calibration.run_dir = asked.run_dir;
  calibration.export_options = options;
  calibration.stop = asked.stop;
  return CalibrationExportWorkflow().Export(calibration).exit_code;
}

/// What is wrong with `run_dir` as a run to export, when it has no config.yaml.
std::string NotARunFolder(const std::string& run_dir) {
  std::error_code error;
  if (!fs::exists(run_dir, error)) {
    return run_dir + ": no such run folder (pass the folder dream run wrote, runs/<name>, or a script SCRIPT.py)";
  }
  if (fs::exists(fs::path(run_dir) / "sweep.json", error)) {
    return run_dir + ": a sweep's folder; export one of its runs, " + (fs::path(run_dir) / "runs").string() +
           "/<run> (its sweep.md lists them)";
  }
  return run_dir + ": not a run folder (it has no config.yaml; pass the folder dream run wrote, runs/<name>)";
}

/// The run whose export `out_dir` holds (its export.json's source_run), or "".
std::string ExportedRunIn(const std::string& out_dir) {
  const fs::path manifest = fs::path(out_dir) / "export.json";
  std::error_code error;
  if (!fs::is_regular_file(manifest, error)) return "";
  try {
    return nlohmann::json::parse(files::ReadFileText(manifest.string())).value("source_run", std::string());
  } catch (const std::exception&) {  // a damaged one is the exporter's to refuse or replace
    return "";
  }
}

}  // namespace

std::vector<std::string> ExportWorkflow::StrategyNames() { return bridge::StrategyNames(); }

int ExportWorkflow::ExportAsAsked(const Asked& asked, std::string* refusal) const {
  bridge::ExportOptions options;
  options.barriers = asked.barriers;
  options.settle_max_steps = asked.settle_steps;
  options.force = asked.force;
  options.python_runtime_dir = asked.python_runtime_dir;
  if (asked.calibration) return ExportCalibration(asked, options);
  if (asked.robots != 0) {
    throw std::runtime_error("--robots " + std::to_string(asked.robots) +
                             ": goes with --calibration (an exported run has its config's robots)");
  }
  if (asked.run_dir.empty()) {
    throw std::runtime_error("pass the run folder to export (dream export RUN), or --calibration --robots N");
  }
  std::error_code error;
  if (asked.config_path.empty() && !fs::exists(fs::path(asked.run_dir) / "config.yaml", error)) {
    throw std::runtime_error(NotARunFolder(asked.run_dir));
  }
  options.strategy = bridge::ParseStrategy(asked.strategy.empty() ? "track" : asked.strategy);
  const Result result = Export({asked.run_dir, asked.out_dir, asked.config_path, options});
  if (result.refused) {
    *refusal = result.refusal;
    return session::kExitRejected;
  }
  return session::kExitOk;
}

std::string ExportWorkflow::OutDir(const Options& options) {
  if (!options.out_dir.empty()) return options.out_dir;
  const std::string config_path =
      options.config_path.empty() ? (fs::path(options.run_dir) / "config.yaml").string() : options.config_path;
  return (fs::path("exports") / run_config::LoadRunConfigFile(config_path).name).string();
}

ExportWorkflow::Result ExportWorkflow::Export(const Options& options) const {
  const std::string out_dir = OutDir(options);
  if (options.out_dir.empty()) {
    std::error_code error;  // a folder that cannot be made is named by the exporter's write
    fs::create_directories(fs::path(out_dir).parent_path(), error);
  }
  const std::string earlier_run = ExportedRunIn(out_dir);
  Result result;
  try {
    result.summary = bridge::ExportSubmission(options.run_dir, out_dir, options.exporter, options.config_path);
  } catch (const bridge::ExportRefused& refused) {
    result.refused = true;
    result.refusal = refused.what();
    return result;
  }
  const bridge::ExportSummary& summary = result.summary;
  out_ << summary.instructions << "\nwritten: " << summary.out_dir << "/UPLOAD.txt, " << summary.upload_dir << "/ ("
       << summary.uploads.size() << " files)\n";
  // Exports go by the config's name: a second run of one config replaces the first's, unless --out says.
  if (!earlier_run.empty() && earlier_run != ExportedRunIn(out_dir)) {
    out_ << "replaced: " << out_dir << " held the export of " << earlier_run
         << " (--out DIR keeps each run's export)\n";
  }
  return result;
}

}  // namespace dream::workflows
