// dream calibrate: fit world.realism's lab model to real runs and write it as
// a realism file (docs/experiments.md, "Calibrating the lab"). The work is
// workflows::CalibrateWorkflow's; this file is options.
#include "command_line.h"
#include "commands.h"
#include "dream/workflows/calibrate_workflow.h"

namespace dream::cli {
namespace {

int RunCalibrate(workflows::CalibrateWorkflow::Options options) {
  options.stop = &StopFlag();
  workflows::CalibrateWorkflow().Calibrate(options);
  return kExitOk;
}

}  // namespace

void DeclareCalibrateCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<workflows::CalibrateWorkflow::Options>(
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
  command->add_option("--poses", args->input.poses_name, "Name of the poses array in .npz/.mat files (3 x N x T)");
  command->add_option("--commands", args->input.commands_name,
                      "Name of the commands array in .npz/.mat files (2 x N x T: v, w sent)");
  command->add_option("--time", args->input.time_name,
                      "Name of the optional time vector (T seconds) in .npz/.mat files");
  command
      ->add_option("--step-period", args->input.step_period_s,
                   "Seconds per step when a file has no time vector (default 0.033)")
      ->check(CLI::Range(0.001, 10.0));
}

}  // namespace dream::cli
