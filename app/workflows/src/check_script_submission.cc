// dream check-submission of a Robotarium script's export (ScriptExport): the
// script, as uploaded, in the official simulator (or the stand-in); its
// debug() verdict is the check's. DREAM's recorder, the upload's main file,
// leaves dream_result.npy in lab_files/, which `dream import` reads as it
// would the lab's.
#include <filesystem>
#include <stdexcept>

#include "dream/files/output_folder.h"
#include "dream/formats/sha256.h"
#include "dream/workflows/check_submission.h"
#include "dream/workflows/script_run_workflow.h"
#include "dream/world/run_verdict.h"
#include "dream/files/json_text.h"

namespace dream::workflows {

namespace fs = std::filesystem;

CheckSubmission::Result CheckSubmission::RunScriptCheck(const ScriptExport::Manifest& manifest) const {
  const std::string main_path = (fs::path(options_.export_dir) / "upload" / manifest.main_file).string();
  std::error_code error;
  if (!fs::is_regular_file(main_path, error)) {
    throw std::runtime_error(main_path + ": missing; export the script again (dream export " + manifest.script + ")");
  }
  if (formats::Sha256::HexOfFile(main_path) != manifest.sha256) {
    throw std::runtime_error(main_path + " was edited after the export (its SHA-256 is not the one in " +
                             ScriptExport::kManifestName + "); export the script again (dream export " +
                             manifest.script + ")");
  }
  if (!manifest.script_file.empty()) {  // the script beside the recorder, as exported
    const std::string script_path = (fs::path(options_.export_dir) / "upload" / manifest.script_file).string();
    if (!fs::is_regular_file(script_path, error) || formats::Sha256::HexOfFile(script_path) != manifest.script_sha256) {
      throw std::runtime_error(
          script_path + " is missing or was edited after the export (its SHA-256 is not the one in " +
          ScriptExport::kManifestName + "); export the script again (dream export " + manifest.script + ")");
    }
  }
  SimulatorChecked();
  const files::OutputFolder out(tools_.choose_folder(
      options_.out_dir,
      // Named after the script, as its run is, not after the recorder that runs it.
      "runs/" + ScriptRunWorkflow::RunName(manifest.script_file.empty() ? manifest.main_file : manifest.script_file) +
          "_check",
      options_.overwrite));
  const std::string workdir = out.MakeSubfolder("lab_files");
  files::OutputFolder(workdir).RemoveFiles("an earlier check's file");
  nlohmann::json report;
  if (std::optional<Result> ended = RunRunner(out, workdir, &report, manifest.main_file)) return *ended;
  const std::vector<std::string> warnings = report.value("warnings", std::vector<std::string>{});
  PrintDebugReport(report, warnings);
  const std::optional<world::RunVerdict> verdict = world::ParseRunVerdict(report.value("verdict", "unknown"));
  Result result;
  result.dir = out.dir();
  nlohmann::ordered_json& check = result.check;
  check["script"] = manifest.main_file;
  check["simulator"] = report.value("simulator", "?");
  check["simulator_path"] = report.value("simulator_path", std::string());
  check["script_ok"] = true;
  // No debug() text (the script never called it): nothing judged, as the lab's own report would have none.
  check["verdict"] = verdict ? world::RunVerdictName(*verdict) : "unknown";
  check["debug_verdict"] = report.value("verdict", "unknown");
  check["python_warnings"] = warnings;
  check["debug_text"] = report.value("debug_text", std::string());
  out.WriteFile("check.json", files::JsonText(check) + "\n");
  out_ << "written: " << out.PathOf("check.json") << "\n";
  result.outcome = verdict == world::RunVerdict::kRejected ? Outcome::kRejected : Outcome::kPassed;
  return result;
}

}  // namespace dream::workflows
