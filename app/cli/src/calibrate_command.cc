// dream calibrate: fit world.realism's lab model to real runs and write it as
// a realism file (docs/experiments.md, "Calibrating the lab").
#include <spdlog/spdlog.h>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "dream/calibration/calibration_picture.h"
#include "dream/calibration/calibration_run.h"
#include "dream/calibration/lab_calibration.h"
#include "dream/calibration/lab_model_check.h"
#include "dream/run_config/run_config.h"
#include "dream/files/atomic_file.h"
#include "dream/files/stop_token.h"
#include "dream/render/render_format.h"

namespace dream::cli {
namespace {

namespace fs = std::filesystem;

struct CalibrateArgs {
  std::vector<std::string> inputs;
  std::string out_path;
  std::string picture_path;  ///< empty: the realism file's name with .png
  std::string base = "lab";
  std::vector<std::string> check_models;  ///< --check: presets or realism files to hold against the runs
  calibration::CalibrationInputOptions options;
};

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

// --check: each model against the runs, side by side; nothing is written.
int RunCheck(const CalibrateArgs& args, const std::vector<calibration::CalibrationRun>& runs,
             const world::RealismParams& base) {
  std::vector<calibration::NamedModel> models;
  for (const std::string& name : args.check_models) models.push_back(ModelNamed(name));
  spdlog::info("holding {} model(s) against {} run(s)", models.size(), runs.size());
  const files::StopToken stop(StopFlag());
  const calibration::CalibrationReport real = calibration::LabCalibration(base, stop).Fit(runs);
  const std::vector<calibration::ModelPrediction> predictions = calibration::LabModelCheck::Predict(runs, models, stop);
  for (const std::string& note : real.notes) spdlog::warn("{}", note);
  std::cout << calibration::LabModelCheck::Table(real, predictions, models);
  if (!args.picture_path.empty()) {
    const std::optional<render::RenderFormat> format = render::RenderFormatOfPath(args.picture_path);
    if (!format || !render::IsPictureFormat(*format)) {
      throw std::runtime_error("--picture " + args.picture_path + ": a picture is .png or .svg");
    }
    calibration::RenderModelCheckPicture(predictions, args.picture_path, *format);
    std::cout << "\nWrote " << args.picture_path << "\n";
  }
  return kExitOk;
}

int RunCalibrate(const CalibrateArgs& args) {
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
  const files::StopToken stop(StopFlag());
  std::vector<calibration::CalibrationRun> runs;
  for (const std::string& input : args.inputs) {
    spdlog::info("reading {}", input);
    runs.push_back(calibration::ReadCalibrationRun(input, args.options));
    stop.ThrowIfRequested();
  }
  if (!args.check_models.empty()) return RunCheck(args, runs, base);
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
  std::cout << report.Text() << "\nWrote " << out.string() << " (use it as world: {realism: {file: " << out.string()
            << "}}, or --set world.realism.file=" << out.string() << ")\nand " << picture << "\n";
  return kExitOk;
}

}  // namespace

void DeclareCalibrateCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<CalibrateArgs>(
      "calibrate",
      "Fit the simulator's lab model (world.realism) to real Robotarium runs and write it as a\n"
      "realism file, with a fit report (each key's value, 95 % interval and the data behind it)\n"
      "and a picture (real against fitted). Keys the runs cannot determine keep --base's value.\n"
      "Inputs: folders made by dream import (or dream run), .npz/.mat files with poses 3 x N x T\n"
      "and commands 2 x N x T (and optionally a time vector), or a .npy of 5 x N x T.\n"
      "With --check, holds lab models (presets or realism files) against the runs instead:\n"
      "delays per speed, 1 s open-loop prediction errors and each key, side by side.\n"
      "Example: dream calibrate runs/lab1 runs/lab2 --out mylab.yaml\n"
      "         dream calibrate runs/lab3 --check ideal,lab_v1,lab,mylab.yaml",
      RunCalibrate);
  command->add_option("runs", args->inputs, "Lab runs: run folders, .npz, .mat or .npy files")->required();
  command->add_option("--out", args->out_path, "The realism file to write (YAML); not with --check");
  command
      ->add_option("--check", args->check_models,
                   "Hold these models (presets or realism files, comma-separated) against the runs; writes nothing")
      ->delimiter(',');
  command->add_option("--picture", args->picture_path,
                      "The picture to draw (.png or .svg; default: --out as .png; with --check: only when given)");
  command->add_option("--base", args->base, "The preset whose values the undetermined keys keep")
      ->check(CLI::IsMember({"lab", "ideal", "lab_v1"}));
  command->add_option("--poses", args->options.poses_name, "Name of the poses array in .npz/.mat files (3 x N x T)");
  command->add_option("--commands", args->options.commands_name,
                      "Name of the commands array in .npz/.mat files (2 x N x T: v, w sent)");
  command->add_option("--time", args->options.time_name,
                      "Name of the optional time vector (T seconds) in .npz/.mat files");
  command
      ->add_option("--step-period", args->options.step_period_s,
                   "Seconds per step when a file has no time vector (default 0.033)")
      ->check(CLI::Range(0.001, 10.0));
}

}  // namespace dream::cli
