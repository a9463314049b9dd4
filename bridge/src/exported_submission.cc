// ExportedSubmission: an export folder read back, every upload file checked
// against the digests the export wrote, for dream import and check-submission.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "dream/bridge/lab_import.h"
#include "dream/formats/npy_file.h"
#include "dream/formats/sha256.h"
#include "dream/bridge/submission_format.h"
#include "dream/files/file_text.h"

namespace dream::bridge {

namespace fs = std::filesystem;

namespace {

/// Compares every file in `upload` with the digests dream export wrote
/// (export.json `upload_sha256`): an edit after the export, a file missing or
/// one the export did not write is an error naming the file.
void CheckUploadDigests(const fs::path& upload, const nlohmann::json& digests, const std::string& manifest_path) {
  const std::string again = ": export the run again (dream export), or undo the change";
  if (!digests.is_object() || digests.empty() || digests.size() > 1000) {
    throw std::runtime_error(manifest_path + ": " + ExportedSubmission::kDigestsKey +
                             " is not a table of file digests; export the run again");
  }
  for (const auto& [name, digest] : digests.items()) {
    if (!digest.is_string() || name.find('/') != std::string::npos || name.empty() || name[0] == '.') {
      throw std::runtime_error(manifest_path + ": " + ExportedSubmission::kDigestsKey + " entry '" + name +
                               "' is no file digest; export the run again");
    }
    const fs::path path = upload / name;
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw std::runtime_error(path.string() + ": missing" + again);
    const std::string actual = formats::Sha256::HexOfFile(path.string());
    if (actual != digest.get<std::string>()) {
      throw std::runtime_error(path.string() + ": changed after the export (its SHA-256 is " + actual + ", " +
                               manifest_path + " says " + digest.get<std::string>() + ")" + again);
    }
  }
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(upload, error)) {
    if (entry.is_regular_file() && !digests.contains(entry.path().filename().string())) {
      throw std::runtime_error(entry.path().string() + ": not a file of this export (" + manifest_path +
                               " lists what it wrote); remove it, or export the run again");
    }
  }
  if (error) throw std::runtime_error(upload.string() + ": cannot list the folder: " + error.message());
}

}  // namespace

ExportedSubmission ExportedSubmission::Read(const std::string& dir) {
  const fs::path root(dir);
  if (!fs::is_directory(root)) throw std::runtime_error(dir + ": not a folder (pass the folder dream export wrote)");
  ExportedSubmission exported;
  exported.dir = dir;
  // Before any file is trusted: each must be as the export wrote it.
  const std::string manifest_path = (root / "export.json").string();
  std::optional<nlohmann::json> manifest;
  if (fs::exists(manifest_path)) {
    try {
      manifest = nlohmann::json::parse(files::ReadFileText(manifest_path));
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(manifest_path + ": not valid JSON: " + e.what());
    }
    if (manifest->is_object() && manifest->contains(kDigestsKey)) {
      CheckUploadDigests(root / "upload", (*manifest)[kDigestsKey], manifest_path);
      exported.digests_checked = true;
    }
  }

  const std::string params_path = (root / "upload" / SubmissionFiles::kParams).string();
  if (!fs::exists(params_path)) {
    throw std::runtime_error(params_path + ": missing; " + dir + " is not a folder written by dream export");
  }
  exported.params = SubmissionParams::FromNpy(formats::ReadNpyFile(params_path, 1 << 20), params_path);
  const std::string config_path = (root / "config.yaml").string();
  if (!fs::exists(config_path)) throw std::runtime_error(config_path + ": missing; export the run again");
  exported.config = run_config::LoadRunConfigFile(config_path);
  // dream export never writes one: the folder was changed by hand.
  if (const std::string refusal = exported.config.LabRefusal("export it"); !refusal.empty()) {
    throw std::runtime_error(refusal + "; dream export never writes such a config, so " + dir +
                             " was changed by hand: export the run again");
  }
  exported.config_text = files::ReadFileText(config_path);
  if (exported.config.num_robots != exported.params.num_robots) {
    throw std::runtime_error(config_path + ": has " + std::to_string(exported.config.num_robots) + " robots but " +
                             params_path + " " + std::to_string(exported.params.num_robots) +
                             "; the export folder was changed by hand — export the run again");
  }
  if (manifest && manifest->is_object() && manifest->contains("source_run") && (*manifest)["source_run"].is_string()) {
    exported.source_run = (*manifest)["source_run"].get<std::string>();
  }
  return exported;
}

int64_t ExportedSubmission::MaxResultValues() const {
  const int64_t rows = int64_t{params.options.settle_max_steps} + params.steps + 1;
  return rows * ResultLayout::Columns(params.num_robots);
}

world::LabVerifierRules::Declaration ExportedSubmission::UploadDeclaration() const {
  // As ExportSubmission computes UPLOAD.txt's "Estimated duration to declare".
  const int64_t max_iterations = params.steps + params.options.settle_max_steps;
  return {params.num_robots, static_cast<double>(max_iterations) * config.world.time_step_s};
}

}  // namespace dream::bridge
