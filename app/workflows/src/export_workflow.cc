#include "dream/workflows/export_workflow.h"

#include <filesystem>

#include "dream/run_config/run_config.h"

namespace dream::workflows {

namespace fs = std::filesystem;

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
  return result;
}

}  // namespace dream::workflows
