// dream calibrate: fit world.realism's lab model to real runs and write it as
// a realism file (docs/calibration.md).
#include "dream/workflows/calibrate_workflow.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "dream/calibration/calibration_picture.h"
#include "dream/calibration/lab_calibration.h"
#include "dream/calibration/lab_model_check.h"
#include "dream/files/atomic_file.h"
#include "dream/files/stop_token.h"
#include "dream/render/render_format.h"
#include "dream/run_config/run_config.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

// A preset's name, or a realism file.
calibration::NamedModel ModelNamed(const std::string& name) {
  world::RealismParams params;
  if (world::RealismParams::FromPreset(name, &params)) return {name, params};
  std::error_code error;
  if (!fs::is_regular_file(name, error)) {
    throw std::runtime_error("--check " + name + ": neither a realism preset (ideal, lab, lab_v1) nor a realism file");
  }
  return {name, run_config::LoadRealismFile(name)};
}

}  // namespace

// --check: each model against the runs, side by side; nothing is written.
void CalibrateWorkflow::Check(const Options& args, const std::vector<calibration::CalibrationRun>& runs) const {
  world::RealismParams base;
  world::RealismParams::FromPreset(args.base, &base);  // checked by Calibrate
  std::vector<calibration::NamedModel> models;
  for (const std::string& name : args.check_models) models.push_back(ModelNamed(name));
  spdlog::info("holding {} model(s) against {} run(s)", models.size(), runs.size());
  const files::StopToken stop = args.stop ? files::StopToken(*args.stop) : files::StopToken();
  const calibration::CalibrationReport real = calibration::LabCalibration(base, stop).Fit(runs);
  const std::vector<calibration::ModelPrediction> predictions = calibration::LabModelCheck::Predict(runs, models, stop);
  for (const std::string& note : real.notes) spdlog::warn("{}", note);
  out_ << calibration::LabModelCheck::Table(real, predictions, models);
  if (!args.picture_path.empty()) {
    const std::optional<render::RenderFormat> format = render::RenderFormatOfPath(args.picture_path);
    if (!format || !render::IsPictureFormat(*format)) {
      throw std::runtime_error("--picture " + args.picture_path + ": a picture is .png or .svg");
    }
    calibration::RenderModelCheckPicture(predictions, args.picture_path, *format);
    out_ << "\nWrote " << args.picture_path << "\n";
  }
}

void CalibrateWorkflow::Calibrate(const Options& args) const {
  if (args.check_models.empty() && args.out_path.empty()) {
    throw std::runtime_error(
        "give --out FILE.yaml (the realism file to write), or --check MODEL to hold models "
        "against the runs");
  }
  world::RealismParams base;
  if (!world::RealismParams::FromPreset(args.base, &base)) {
    throw std::runtime_error("--base " + args.base + ": not a realism preset (ideal, lab, lab_v1)");
  }
  // Ctrl-C or SIGTERM: the fit stops within a fraction of a second
  // (files::Stopped, exit 130) and nothing is written.
  const files::StopToken stop = args.stop ? files::StopToken(*args.stop) : files::StopToken();
  std::vector<calibration::CalibrationRun> runs;
  for (const std::string& input : args.inputs) {
    spdlog::info("reading {}", input);
    runs.push_back(calibration::ReadCalibrationRun(input, args.input));
    stop.ThrowIfRequested();
  }
  if (!args.check_models.empty()) {
    Check(args, runs);
    return;
  }
  const fs::path out(args.out_path);
  if (out.extension() != ".yaml" && out.extension() != ".yml") {
    throw std::runtime_error("--out " + args.out_path + ": a realism file is YAML; name it like mylab.yaml");
  }
  const std::string picture =
      args.picture_path.empty() ? fs::path(out).replace_extension(".png").string() : args.picture_path;
  const std::optional<render::RenderFormat> format = render::RenderFormatOfPath(picture);
  if (!format || !render::IsPictureFormat(*format)) {
    throw std::runtime_error("--picture " + picture + ": a picture is .png or .svg");
  }
  spdlog::info("fitting the lab model to {} run(s)", runs.size());
  const calibration::CalibrationReport report = calibration::LabCalibration(base, stop).Fit(runs);
  stop.ThrowIfRequested();  // asked as the fit ended: still nothing written
  if (!out.parent_path().empty()) fs::create_directories(out.parent_path());
  files::WriteFileAtomically(out.string(), report.RealismYaml());
  calibration::RenderCalibrationPicture(report, picture, *format);
  out_ << report.Text() << "\nWrote " << out.string() << " (use it as world: {realism: {file: " << out.string()
       << "}}, or --set world.realism.file=" << out.string() << ")\nand " << picture << "\n";
}

}  // namespace dream::workflows
