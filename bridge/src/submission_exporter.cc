#include "dream/sim/file_text.h"
#include "dream/bridge/submission_exporter.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dream/bridge/npy_file.h"
#include "dream/sim/output_folder.h"
#include "dream/bridge/submission_format.h"
#include "dream/bridge/submission_params.h"
#include "dream/config/run_config.h"

namespace dream::bridge {
namespace {

std::string JoinProblems(const std::vector<ExportProblem>& problems) {
  std::string text = "the Robotarium would refuse this run (" + std::to_string(problems.size()) + " problem" +
                     (problems.size() == 1 ? "" : "s") + "):";
  for (const ExportProblem& p : problems) text += "\n  " + p.Text();
  return text;
}

std::string Seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", s);
  return text;
}

}  // namespace

ExportRefused::ExportRefused(std::vector<ExportProblem> problems)
    : std::runtime_error(JoinProblems(problems)), problems_(std::move(problems)) {}

ExportSummary ExportSubmission(const std::string& run_dir, const std::string& out_dir, const ExportOptions& options,
                               const std::string& config_path) {
  namespace fs = std::filesystem;
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument("export options: " + error);
  const std::string config_file = config_path.empty() ? (fs::path(run_dir) / "config.yaml").string() : config_path;
  const std::string log_file = (fs::path(run_dir) / "run.lcmlog").string();
  if (!fs::is_directory(run_dir)) throw std::runtime_error(run_dir + ": not a folder (pass a run folder written by dream run)");
  if (!fs::exists(config_file)) {
    throw std::runtime_error(config_file + ": missing; this run folder was written by an older dream run — "
                             "pass its config with --config FILE");
  }
  if (!fs::exists(log_file)) throw std::runtime_error(log_file + ": missing; pass a run folder written by dream run");

  // Read and check everything before writing anything.
  const config::RunConfig config = config::LoadRunConfigFile(config_file);
  const std::string config_text = sim::ReadFileText(config_file);
  RunEnd end;
  const RunTrack track = ReadRunTrack(log_file, &end);
  if (track.num_robots != config.num_robots) {
    throw std::runtime_error(log_file + ": the log has " + std::to_string(track.num_robots) + " robots, its config " +
                             config_file + " " + std::to_string(config.num_robots) + "; is it the right config?");
  }
  if (track.last_step() < 1) throw std::runtime_error(log_file + ": the run has no step to export");
  const std::vector<ExportProblem> problems = PreValidate(track, end, config.world, options.settle_max_steps);
  if (!problems.empty()) throw ExportRefused(problems);

  const int n = track.num_robots;
  const int64_t steps = track.last_step();
  SubmissionParams params;
  params.num_robots = n;
  params.steps = steps;
  params.options = options;
  params.wheel_radius_m = config.world.wheel_radius_m;
  params.base_length_m = config.world.base_length_m;
  params.max_wheel_speed_radps = config.world.max_wheel_speed_radps;

  NpyArray initial;
  initial.shape = {3, n};
  initial.values.resize(static_cast<size_t>(3 * n));
  for (int i = 0; i < n; ++i) {
    const sim::Pose2& p = track.pose(0, i);
    initial.values[static_cast<size_t>(i)] = p.x_m;
    initial.values[static_cast<size_t>(n + i)] = p.y_m;
    initial.values[static_cast<size_t>(2 * n + i)] = p.theta_rad;
  }
  NpyArray poses;
  poses.shape = {steps + 1, 3, n};
  poses.values.resize(static_cast<size_t>((steps + 1) * 3 * n));
  NpyArray commands;
  commands.shape = {steps, 2, n};
  commands.values.resize(static_cast<size_t>(steps * 2 * n));
  const auto un = static_cast<size_t>(n);
  for (int64_t k = 0; k <= steps; ++k) {
    double* row = &poses.values[static_cast<size_t>(k) * 3 * un];
    const sim::Pose2* step_poses = &track.poses[static_cast<size_t>(k) * un];
    for (size_t i = 0; i < un; ++i) {
      row[i] = step_poses[i].x_m;
      row[un + i] = step_poses[i].y_m;
      row[2 * un + i] = step_poses[i].theta_rad;
    }
    if (k == steps) break;
    double* command_row = &commands.values[static_cast<size_t>(k) * 2 * un];
    const sim::UnicycleCommand* step_commands = &track.commands[static_cast<size_t>(k) * un];
    for (size_t i = 0; i < un; ++i) {
      command_row[i] = step_commands[i].v_mps;
      command_row[un + i] = step_commands[i].w_radps;
    }
  }

  ExportSummary summary;
  summary.num_robots = n;
  summary.steps = steps;
  summary.max_iterations = steps + options.settle_max_steps;
  summary.estimated_duration_s = static_cast<double>(summary.max_iterations) * config.world.time_step_s;
  summary.uploads = {SubmissionFiles::kMainScript, SubmissionFiles::kParams, SubmissionFiles::kInitialPoses,
                     SubmissionFiles::kReferencePoses, SubmissionFiles::kReferenceCommands};

  const std::string source_run = fs::weakly_canonical(fs::absolute(run_dir)).string();
  nlohmann::ordered_json manifest;
  manifest["format"] = "dream-robotarium-export";
  manifest["format_version"] = kFormatVersion;
  manifest["run"] = config.name;
  manifest["source_run"] = source_run;
  manifest["strategy"] = StrategyName(options.strategy);
  manifest["barriers"] = options.barriers;
  manifest["robots"] = n;
  manifest["steps"] = steps;
  manifest["settle_max_steps"] = options.settle_max_steps;
  manifest["estimated_duration_s"] = summary.estimated_duration_s;
  manifest["main"] = SubmissionFiles::kMainScript;
  manifest["upload"] = summary.uploads;
  manifest["result"] = SubmissionFiles::kResult;

  std::string& text = summary.instructions;
  text += "Robotarium submission made by dream export from the run '" + config.name + "'.\n\n";
  text += "Upload every file in upload/ (" + std::to_string(summary.uploads.size()) + " files, no folders):\n";
  for (size_t i = 0; i < summary.uploads.size(); ++i) {
    text += "  " + summary.uploads[i] + (i == 0 ? "    <- mark this file as MAIN" : "") + "\n";
  }
  text += "\nNumber of robots to declare: " + std::to_string(n) + "\n";
  text += "Estimated duration to declare: " + Seconds(summary.estimated_duration_s) + " s (" + std::to_string(steps) +
          " steps + at most " + std::to_string(options.settle_max_steps) + " settle steps of " +
          Seconds(config.world.time_step_s * 1000) + " ms; the lab's own start-up drive comes on top)\n";
  text += std::string("Strategy: ") + StrategyName(options.strategy) +
          (options.strategy == Strategy::kTrack ? " (recorded commands plus feedback on the pose error)"
                                                : " (recorded commands, open loop)") +
          (options.barriers ? ", through the Robotarium's barrier certificates" : "") + "\n";
  summary.warnings = StartUpWarnings(track);
  for (const std::string& warning : summary.warnings) text += "\nWARNING: " + warning + "\n";
  text += "\nThe script saves dream_result.npy (poses, commands sent, wall-clock stamps; rewritten\n"
          "every " + std::to_string(options.save_every_steps) +
          " steps). Download it from the lab's results, then:\n"
          "  dream import dream_result.npy --export <this folder> --out <lab run folder>\n"
          "  dream compare <simulated run folder> <lab run folder>\n"
          "Before uploading, try it: dream check-submission <this folder> --out <folder>\n";

  sim::OutputFolder out(out_dir);
  const sim::OutputFolder upload(out.MakeSubfolder("upload"));
  upload.WriteFile(SubmissionFiles::kMainScript, SubmissionScriptTemplate());
  upload.WriteFile(SubmissionFiles::kParams, EncodeNpy(params.ToNpy()));
  upload.WriteFile(SubmissionFiles::kInitialPoses, EncodeNpy(initial));
  upload.WriteFile(SubmissionFiles::kReferencePoses, EncodeNpy(poses));
  upload.WriteFile(SubmissionFiles::kReferenceCommands, EncodeNpy(commands));
  out.WriteFile("config.yaml", config_text);
  out.WriteFile("export.json", manifest.dump(2) + "\n");
  out.WriteFile("UPLOAD.txt", text);
  summary.out_dir = out.dir();
  summary.upload_dir = upload.dir();
  return summary;
}

}  // namespace dream::bridge
