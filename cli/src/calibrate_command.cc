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
#include "dream/bridge/calibration_picture.h"
#include "dream/bridge/calibration_run.h"
#include "dream/bridge/lab_calibration.h"
#include "dream/node/atomic_file.h"
#include "dream/render/render_format.h"

namespace dream::cli {
namespace {

namespace fs = std::filesystem;

struct CalibrateArgs {
  std::vector<std::string> inputs;
  std::string out_path;
  std::string picture_path;  ///< empty: the realism file's name with .png
  std::string base = "lab";
  bridge::CalibrationInputOptions options;
};

int RunCalibrate(const CalibrateArgs& args) {
  const fs::path out(args.out_path);
  if (out.extension() != ".yaml" && out.extension() != ".yml") {
    throw std::runtime_error("--out " + args.out_path + ": a realism file is YAML; name it like mylab.yaml");
  }
  const std::string picture =
      args.picture_path.empty() ? fs::path(out).replace_extension(".png").string() : args.picture_path;
  const std::optional<sim::RenderFormat> format = sim::RenderFormatOfPath(picture);
  if (!format || !sim::IsPictureFormat(*format)) {
    throw std::runtime_error("--picture " + picture + ": a picture is .png or .svg");
  }
  sim::RealismParams base;
  if (!sim::RealismParams::FromPreset(args.base, &base)) {
    throw std::runtime_error("--base " + args.base + ": not a realism preset (ideal, lab)");
  }
  std::vector<bridge::CalibrationRun> runs;
  for (const std::string& input : args.inputs) {
    spdlog::info("reading {}", input);
    runs.push_back(bridge::ReadCalibrationRun(input, args.options));
    if (StopFlag()) return kExitInterrupted;
  }
  spdlog::info("fitting the lab model to {} run(s)", runs.size());
  const bridge::CalibrationReport report = bridge::LabCalibration(base).Fit(runs);
  if (!out.parent_path().empty()) fs::create_directories(out.parent_path());
  sim::WriteFileAtomically(out.string(), report.RealismYaml());
  bridge::RenderCalibrationPicture(report, picture, *format);
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
      "Example: dream calibrate runs/lab1 runs/lab2 --out mylab.yaml",
      RunCalibrate);
  command->add_option("runs", args->inputs, "Lab runs: run folders, .npz, .mat or .npy files")->required();
  command->add_option("--out", args->out_path, "The realism file to write (YAML)")->required();
  command->add_option("--picture", args->picture_path, "The picture to draw (.png or .svg; default: --out as .png)");
  command->add_option("--base", args->base, "The preset whose values the undetermined keys keep")
      ->check(CLI::IsMember({"lab", "ideal"}));
  command->add_option("--poses", args->options.poses_name, "Name of the poses array in .npz/.mat files (3 x N x T)");
  command->add_option("--commands", args->options.commands_name,
                      "Name of the commands array in .npz/.mat files (2 x N x T: v, w sent)");
  command->add_option("--time", args->options.time_name,
                      "Name of the optional time vector (T seconds) in .npz/.mat files");
  command->add_option("--step-period", args->options.step_period_s,
                      "Seconds per step when a file has no time vector (default 0.033)")
      ->check(CLI::Range(0.001, 10.0));
}

}  // namespace dream::cli
