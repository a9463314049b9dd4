#include "dream/files/file_text.h"
#include "dream/bridge/submission_exporter.h"

#include "dream/run_config/startup_drive_check.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dream/agent_host/controller_registry.h"
#include "dream/bridge/controller_module_copy.h"
#include "dream/bridge/flat_python_runtime.h"
#include "dream/bridge/lab_import.h"
#include "dream/formats/sha256.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/obstacle_schedule.h"
#include "dream/files/json_text.h"
#include "dream/node/run_summary.h"
#include "dream/files/output_folder.h"
#include "dream/kind_api/controller_kind.h"
#include "dream/bridge/submission_format.h"
#include "dream/bridge/submission_params.h"
#include "dream/run_config/run_config.h"
#include "dream/world/run_verdict.h"

namespace dream::bridge {
namespace {

std::string JoinProblems(const std::string& log_file, const std::vector<ExportProblem>& problems) {
  std::string text = log_file + ": the Robotarium would refuse this run (" + std::to_string(problems.size()) +
                     " problem" + (problems.size() == 1 ? "" : "s") + "):";
  for (const ExportProblem& p : problems) text += "\n  " + p.Text();
  return text;
}

std::string Seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", s);
  return text;
}

/// The step limit the simulated run had: summary.json's max_steps (which
/// includes a dream run --steps), else the config's.
int64_t RunStepLimit(const std::string& run_dir, const run_config::RunConfig& config) {
  const std::string summary_path = (std::filesystem::path(run_dir) / node::RunSummary::kFileName).string();
  if (!std::filesystem::exists(summary_path)) return config.sim.max_steps;
  const node::RunSummary summary = node::RunSummary::Read(summary_path);
  if (summary.Has("max_steps") && summary.max_steps >= 1) return summary.max_steps;
  throw std::runtime_error(summary_path + ": has no max_steps (a whole number >= 1); is it a dream run's summary?");
}

/// The reasons summary.json gives for a not_ready verdict (lost robots,
/// command conflicts, bad messages, an unmet goal, ...), as export problems;
/// none for a run folder without summary.json (an older dream run). Those
/// PreValidate finds again in the log (controller_failed, did_not_finish) and
/// the pose rules it re-checks are left to it.
std::vector<ExportProblem> NotReadyReasons(const std::string& run_dir) {
  const std::string summary_path = (std::filesystem::path(run_dir) / node::RunSummary::kFileName).string();
  std::vector<ExportProblem> problems;
  if (!std::filesystem::exists(summary_path)) return problems;
  // Written before verdict reasons, a summary has none: nothing to add.
  for (const world::VerdictReason& reason : node::RunSummary::Read(summary_path).verdict_reasons) {
    if (reason.verdict != world::RunVerdict::kNotReady || reason.rule == "controller_failed" ||
        reason.rule == "did_not_finish") {
      continue;
    }
    problems.push_back({reason.rule, -1, -1, -1, reason.problem, reason.find_out + "; or export anyway with --force"});
  }
  return problems;
}

/// What the controller strategy ships besides the script and the params.
struct ControllerFiles {
  std::string spec_json;    ///< module: the bare file name
  std::string module_name;  ///< e.g. go_to_goal.py
  std::string module_text;
  std::vector<FlatPythonRuntime::File> runtime;
};

ControllerFiles ReadControllerFiles(const run_config::RunConfig& config, const kind_api::ControllerKind& kind,
                                    const std::string& config_file, const std::string& runtime_dir) {
  if (runtime_dir.empty())
    throw std::invalid_argument("export options: the controller strategy needs python_runtime_dir");
  ControllerFiles files;
  nlohmann::ordered_json spec = nlohmann::ordered_json::parse(kind.runtime_spec(config));
  const std::string module_path = spec["module"].get<std::string>();
  files.module_text = files::ReadFileText(module_path);
  const FlatPythonRuntime runtime = FlatPythonRuntime::Read(runtime_dir);
  files.module_name = FlatPythonRuntime::ControllerFileName(
      module_path, files.module_text, runtime.ImportedModules({SubmissionScriptTemplate()}), config_file);
  // In the submission the module sits beside the script, and config errors
  // name the export's copy of the config.
  spec["module"] = files.module_name;
  spec["config_file"] = "config.yaml";
  files.spec_json = files::JsonText(spec, -1);
  files.runtime = runtime.files();
  return files;
}

/// An export goes into a folder of its own: not a run's (its config.yaml
/// would be replaced), and an upload/ there must be an earlier export's.
void CheckExportFolder(const std::string& out_dir) {
  namespace fs = std::filesystem;
  std::error_code error;
  for (const char* run_file : {"run.lcmlog", "summary.json"}) {
    if (fs::exists(fs::path(out_dir) / run_file, error)) {
      throw std::runtime_error("--out " + out_dir + " holds a run (" + run_file +
                               "); an export would replace its config.yaml: choose another --out");
    }
  }
  // A link named upload is refused later, as leading outside the folder.
  if (fs::is_directory(fs::symlink_status(fs::path(out_dir) / "upload", error)) &&
      !fs::exists(fs::path(out_dir) / "export.json", error)) {
    throw std::runtime_error("--out " + out_dir + " has an upload/ that no dream export wrote (no export.json " +
                             "beside it): choose another --out");
  }
}

/// What an export is made from, read and checked before anything is written.
struct ExportInput {
  std::string config_file;
  std::string log_file;
  run_config::RunConfig config;
  std::string config_text;
  RunTrack track;
  RunEnd end;
  bool controller = false;  ///< the controller strategy
  /// The controller strategy's: the run's kind, when its robots run in the
  /// Python runtime (what a submission ships; the lab runs Python only).
  std::shared_ptr<const kind_api::ControllerKind> python_kind;
  int64_t steps = 0;                ///< the submission's step limit
  std::vector<std::string> forced;  ///< problems --force turned into warnings
};

/// The run folder's files, named in the errors; nothing read yet.
ExportInput CheckExportPaths(const std::string& run_dir, const std::string& out_dir, const ExportOptions& options,
                             const std::string& config_path) {
  namespace fs = std::filesystem;
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument("export options: " + error);
  ExportInput input;
  input.config_file = config_path.empty() ? (fs::path(run_dir) / "config.yaml").string() : config_path;
  input.log_file = (fs::path(run_dir) / "run.lcmlog").string();
  if (!fs::is_directory(run_dir))
    throw std::runtime_error(run_dir + ": not a folder (pass a run folder written by dream run)");
  if (!config_path.empty() && !fs::is_regular_file(config_path)) {
    throw std::runtime_error("--config " + config_path + ": no such file");
  }
  if (!fs::exists(input.config_file)) {
    throw std::runtime_error(input.config_file +
                             ": missing; this run folder was written by an older dream run — "
                             "pass its config with --config FILE");
  }
  CheckExportFolder(out_dir);
  if (!fs::exists(input.log_file)) {
    throw std::runtime_error(input.log_file + ": missing; pass a run folder written by dream run");
  }
  return input;
}

/// What the controller strategy cannot export: a C++ controller, an
/// obstacle schedule too large to upload.
void AddControllerProblems(const ExportInput& input, std::vector<ExportProblem>* problems) {
  const run_config::RunConfig& config = input.config;
  if (input.python_kind == nullptr) {
    const config::ConfigNode kind = config.controller.Optional("kind");
    problems->push_back({"strategy", -1, -1, -1,
                         "the controller strategy runs the run's Python controller in the submission, and this "
                         "run's controller (kind '" +
                             (kind.IsDefined() ? kind.AsString() : std::string("?")) + "' in " + input.config_file +
                             ") is C++: the lab runs Python only",
                         "export with --strategy track (the recorded run in closed loop) or --strategy replay; "
                         "or write the controller in Python (controller: {kind: python, module: ..., class: ...})"});
  }
  const int64_t schedule_bytes = ObstacleScheduleBytes(static_cast<int64_t>(config.obstacles.size()), input.steps);
  if (schedule_bytes > kMaxObstacleScheduleBytes) {
    problems->push_back({"obstacle_schedule", -1, -1, -1,
                         "upload/dream_obstacles.npy would hold " + std::to_string(config.obstacles.size()) +
                             " obstacles at each of " + std::to_string(input.steps + 1) + " steps, " +
                             std::to_string(schedule_bytes >> 20) + " MiB (at most " +
                             std::to_string(kMaxObstacleScheduleBytes >> 20) + " MiB)",
                         "fewer obstacles, or fewer steps (the config's steps: bounds the controller strategy's run)"});
  }
}

/// Reads the run and checks it as the lab would.
/// @throws ExportRefused with every problem not forced.
ExportInput ReadAndCheck(const std::string& run_dir, const std::string& out_dir, const ExportOptions& options,
                         const std::string& config_path) {
  ExportInput input = CheckExportPaths(run_dir, out_dir, options, config_path);
  input.config = run_config::LoadRunConfigFile(input.config_file);
  // Declared for simulation only: nothing about its recording matters.
  if (const std::string refusal = input.config.LabRefusal("export it"); !refusal.empty()) {
    throw std::runtime_error(refusal);
  }
  input.config_text = files::ReadFileText(input.config_file);
  const run_config::BarrierConfig& barriers = input.config.barriers;
  if (options.barriers && barriers.kind != run_config::BarrierConfig::Kind::kNone &&
      barriers.apply_in == run_config::BarrierConfig::ApplyIn::kController) {
    throw std::runtime_error(input.config_file + ": barriers: apply_in: controller: the controller applies its " +
                             "certificate itself (dream.barriers ships with it); --barriers would put a second " +
                             "one on its commands. Drop --barriers, or set apply_in: world");
  }
  input.track = ReadRunTrack(input.log_file, &input.end);
  const run_config::RunConfig& config = input.config;
  if (input.track.num_robots != config.num_robots) {
    throw std::runtime_error(input.log_file + ": the log has " + std::to_string(input.track.num_robots) +
                             " robots, its config " + input.config_file + " " + std::to_string(config.num_robots) +
                             "; is it the right config?");
  }
  if (input.track.last_step() < 1) throw std::runtime_error(input.log_file + ": the run has no step to export");
  input.controller = options.strategy == Strategy::kController;
  if (input.controller) {
    std::shared_ptr<const kind_api::ControllerKind> kind = agent_host::ControllerRegistry::KindOf(config);
    if (kind != nullptr && kind->runtime == kind_api::ControllerKind::Runtime::kPython)
      input.python_kind = std::move(kind);
  }
  // The controller strategy runs until every robot is done, at most the run's step limit.
  input.steps = input.python_kind != nullptr ? RunStepLimit(run_dir, config) : input.track.last_step();
  std::vector<ExportProblem> problems;
  if (input.controller) AddControllerProblems(input, &problems);
  // What UPLOAD.txt tells the user to declare: the lab's verifier holds the run to it.
  const world::LabVerifierRules::Declaration declared{
      config.num_robots, static_cast<double>(input.steps + options.settle_max_steps) * config.world.time_step_s};
  // --force exports a run whose robots were lost, or that summary.json
  // calls not_ready; the lab's rules are never forced.
  auto force_or_refuse = [&](ExportProblem problem, bool forcible) {
    if (options.force && forcible) {
      input.forced.push_back(problem.Text() + " (exported anyway: --force)");
    } else {
      problems.push_back(std::move(problem));
    }
  };
  for (ExportProblem& problem : PreValidate(input.track, input.end, config.world, options.settle_max_steps, LabLimits{},
                                            input.steps, declared)) {
    const bool forcible = problem.rule == "lost_robot";
    force_or_refuse(std::move(problem), forcible);
  }
  for (ExportProblem& problem : NotReadyReasons(run_dir)) force_or_refuse(std::move(problem), true);
  if (!problems.empty()) throw ExportRefused(input.log_file, problems);
  return input;
}

/// The start poses, and (track, replay) the recorded poses and commands of every step.
struct ReferenceArrays {
  formats::NpyArray initial;
  formats::NpyArray poses;
  formats::NpyArray commands;
};

/// `start_poses`: the initial conditions the script asks the lab for (the
/// config's for `world.start: placed`, whose step 0 is where the start-up
/// drive ended; else the track's step 0).
ReferenceArrays MakeReferenceArrays(const RunTrack& track, bool controller,
                                    const std::vector<world::Pose2>& start_poses) {
  const int n = track.num_robots;
  const auto un = static_cast<size_t>(n);
  ReferenceArrays arrays;
  arrays.initial.shape = {3, n};
  arrays.initial.values.resize(3 * un);
  for (size_t i = 0; i < un; ++i) {
    const world::Pose2& p = start_poses.size() == un ? start_poses[i] : track.pose(0, static_cast<int>(i));
    arrays.initial.values[i] = p.x_m;
    arrays.initial.values[un + i] = p.y_m;
    arrays.initial.values[2 * un + i] = p.theta_rad;
  }
  const int64_t reference_steps = controller ? -1 : track.last_step();
  arrays.poses.shape = {reference_steps + 1, 3, n};
  arrays.poses.values.resize(static_cast<size_t>((reference_steps + 1) * 3 * n));
  arrays.commands.shape = {std::max<int64_t>(reference_steps, 0), 2, n};
  arrays.commands.values.resize(static_cast<size_t>(std::max<int64_t>(reference_steps, 0) * 2 * n));
  for (int64_t k = 0; k <= reference_steps; ++k) {
    double* row = &arrays.poses.values[static_cast<size_t>(k) * 3 * un];
    const world::Pose2* step_poses = &track.poses[static_cast<size_t>(k) * un];
    for (size_t i = 0; i < un; ++i) {
      row[i] = step_poses[i].x_m;
      row[un + i] = step_poses[i].y_m;
      row[2 * un + i] = step_poses[i].theta_rad;
    }
    if (k == reference_steps) break;
    double* command_row = &arrays.commands.values[static_cast<size_t>(k) * 2 * un];
    const world::UnicycleCommand* step_commands = &track.commands[static_cast<size_t>(k) * un];
    for (size_t i = 0; i < un; ++i) {
      command_row[i] = step_commands[i].v_mps;
      command_row[un + i] = step_commands[i].w_radps;
    }
  }
  return arrays;
}

SubmissionParams MakeParams(const ExportInput& input, const ExportOptions& options) {
  const run_config::RunConfig& config = input.config;
  SubmissionParams params;
  params.num_robots = input.track.num_robots;
  params.steps = input.steps;
  params.options = options;
  // The certificate the simulator applied is the one the lab's script applies.
  if (config.barriers.InWorld()) {
    params.options.barriers = true;
    params.options.barrier_params = config.barriers.unicycle;
  }
  params.wheel_radius_m = config.world.wheel_radius_m;
  params.base_length_m = config.world.base_length_m;
  params.max_wheel_speed_radps = config.world.max_wheel_speed_radps;
  params.stop_when_done = input.controller && config.sim.stop_when_done;
  params.max_abs_v_mps = config.sim.max_abs_v_mps;
  params.max_abs_w_radps = config.sim.max_abs_w_radps;
  return params;
}

/// export.json, without the upload files' digests.
nlohmann::ordered_json Manifest(const ExportInput& input, const ExportSummary& summary, const SubmissionParams& params,
                                const std::string& run_dir, const std::string& module_name) {
  namespace fs = std::filesystem;
  const ExportOptions& options = params.options;
  nlohmann::ordered_json manifest;
  manifest["format"] = "dream-robotarium-export";
  manifest["format_version"] = kFormatVersion;
  manifest["run"] = input.config.name;
  manifest["source_run"] = fs::weakly_canonical(fs::absolute(run_dir)).string();
  manifest["strategy"] = StrategyName(options.strategy);
  manifest["barriers"] = options.barriers;
  if (options.barriers) {
    const barriers::UnicycleBarrierParams& b = options.barrier_params;
    nlohmann::ordered_json barrier;
    barrier["from"] = input.config.barriers.InWorld() ? "config" : "--barriers";
    barrier["safety_radius_m"] = b.safety_radius_m;
    barrier["barrier_gain"] = b.barrier_gain;
    barrier["projection_distance_m"] = b.projection_distance_m;
    barrier["magnitude_limit_mps"] = b.magnitude_limit_mps;
    barrier["boundary_m"] = b.boundary ? nlohmann::ordered_json::array({b.boundary->x_min_m, b.boundary->x_max_m,
                                                                        b.boundary->y_min_m, b.boundary->y_max_m})
                                       : nlohmann::ordered_json();
    manifest["barrier_params"] = barrier;
  }
  if (options.calibration) manifest["calibration"] = true;
  manifest["robots"] = summary.num_robots;
  manifest["steps"] = summary.steps;
  manifest["recorded_steps"] = input.track.last_step();
  if (input.controller) {
    manifest["stop_when_done"] = params.stop_when_done;
    manifest["controller_module"] = module_name;
  }
  manifest["settle_max_steps"] = options.settle_max_steps;
  manifest["estimated_duration_s"] = summary.estimated_duration_s;
  manifest["main"] = SubmissionFiles::kMainScript;
  manifest["upload"] = summary.uploads;
  manifest["result"] = SubmissionFiles::kResult;
  return manifest;
}

/// UPLOAD.txt: what to upload and declare, the warnings, what to do with the result.
std::string Instructions(const ExportInput& input, const ExportSummary& summary, const SubmissionParams& params) {
  const ExportOptions& options = params.options;
  const double time_step_s = input.config.world.time_step_s;
  std::string text = "Robotarium submission made by dream export from the run '" + input.config.name + "'.\n";
  if (options.calibration) {
    text +=
        "It is the calibration drive: every robot drives the same open-loop program (steps in v\n"
        "and w from rest, turns in place, an arc), from which dream calibrate fits your lab's model.\n";
  }
  text += "\n";
  text += "Upload every file in upload/ (" + std::to_string(summary.uploads.size()) + " files, no folders):\n";
  for (size_t i = 0; i < summary.uploads.size(); ++i) {
    text += "  " + summary.uploads[i] + (i == 0 ? "    <- mark this file as MAIN" : "") + "\n";
  }
  text += "\nNumber of robots to declare: " + std::to_string(summary.num_robots) + "\n";
  text += "Estimated duration to declare: " + Seconds(summary.estimated_duration_s) + " s (" +
          (input.controller ? "at most " : "") + std::to_string(summary.steps) + " steps + at most " +
          std::to_string(options.settle_max_steps) + " settle steps of " + Seconds(time_step_s * 1000) +
          " ms; the lab's own start-up drive comes on top)\n";
  text += "Strategy: " + std::string(StrategyName(options.strategy)) + " (" + StrategyDescription(options.strategy) +
          ")" +
          (options.barriers
               ? std::string(", through the Robotarium's unicycle barrier certificate") +
                     (input.config.barriers.InWorld() ? " (the config's barriers:, as the simulator applied it)" : "")
               : std::string()) +
          "\n";
  if (input.controller) {
    text += std::string("The run ends after ") + std::to_string(summary.steps) + " steps" +
            (params.stop_when_done ? ", or earlier once every robot reports done" : "") + " (the simulated run took " +
            std::to_string(input.track.last_step()) + ")\n";
  }
  for (const std::string& warning : summary.warnings) text += "\nWARNING: " + warning + "\n";
  text +=
      "\nThe script saves dream_result.npy (poses, commands sent, wall-clock stamps; rewritten\n"
      "every " +
      std::to_string(options.save_every_steps) +
      " steps). Download it from the lab's results, then:\n"
      "  dream import dream_result.npy --export <this folder> --out <lab run folder>\n"
      "  dream compare <simulated run folder> <lab run folder>\n"
      "Before uploading, try it: dream check-submission <this folder> --out <folder>\n";
  if (options.calibration) {
    text +=
        "\nThe lab model: dream_result.npy holds every pose the lab measured and every command sent,\n"
        "which is what dream calibrate fits. Download it (keep it: each lab run is data about your\n"
        "lab), import it as above, then:\n"
        "  dream calibrate <lab run folder> --out mylab.yaml\n"
        "and run any config on your lab's model: --set world.realism.file=mylab.yaml\n"
        "(docs/experiments.md, \"Calibrating the lab: dream calibrate\").\n";
  }
  return text;
}

/// upload/'s files, by name, in UPLOAD.txt's order.
std::vector<std::pair<std::string, std::string>> UploadFiles(const SubmissionParams& params,
                                                             const ReferenceArrays& arrays,
                                                             const ControllerFiles& controller_files,
                                                             const formats::NpyArray& obstacles, bool controller) {
  std::vector<std::pair<std::string, std::string>> files = {
      {SubmissionFiles::kMainScript, SubmissionScriptTemplate()},
      {SubmissionFiles::kParams, formats::EncodeNpy(params.ToNpy())},
      {SubmissionFiles::kInitialPoses, formats::EncodeNpy(arrays.initial)}};
  if (controller) {
    files.emplace_back(SubmissionFiles::kControllerSpec, formats::EncodeNpyBytes(controller_files.spec_json));
    files.emplace_back(SubmissionFiles::kObstacles, formats::EncodeNpy(obstacles));
    files.emplace_back(controller_files.module_name, controller_files.module_text);
    for (const FlatPythonRuntime::File& file : controller_files.runtime) files.emplace_back(file.name, file.text);
  } else {
    files.emplace_back(SubmissionFiles::kReferencePoses, formats::EncodeNpy(arrays.poses));
    files.emplace_back(SubmissionFiles::kReferenceCommands, formats::EncodeNpy(arrays.commands));
  }
  return files;
}

}  // namespace

ExportRefused::ExportRefused(const std::string& log_file, std::vector<ExportProblem> problems)
    : std::runtime_error(JoinProblems(log_file, problems)), problems_(std::move(problems)) {}

ExportSummary ExportSubmission(const std::string& run_dir, const std::string& out_dir, const ExportOptions& options,
                               const std::string& config_path) {
  // Read and check everything before writing anything.
  const ExportInput input = ReadAndCheck(run_dir, out_dir, options, config_path);
  const run_config::RunConfig& config = input.config;
  ControllerFiles controller_files;
  formats::NpyArray obstacles;
  if (input.controller) {
    controller_files = ReadControllerFiles(config, *input.python_kind, input.config_file, options.python_runtime_dir);
    obstacles = ObstacleSchedule(config.obstacles, config.world.time_step_s, input.steps);
  }
  const SubmissionParams params = MakeParams(input, options);
  const ReferenceArrays arrays = MakeReferenceArrays(
      input.track, input.controller,
      config.start == run_config::WorldStart::kPlaced ? config.initial_poses : std::vector<world::Pose2>());

  ExportSummary summary;
  summary.num_robots = input.track.num_robots;
  summary.steps = input.steps;
  summary.max_iterations = input.steps + options.settle_max_steps;
  summary.estimated_duration_s = static_cast<double>(summary.max_iterations) * config.world.time_step_s;
  const auto upload_files = UploadFiles(params, arrays, controller_files, obstacles, input.controller);
  for (const auto& file : upload_files) summary.uploads.push_back(file.first);
  summary.warnings = input.forced;
  for (std::string& warning : StartUpWarnings(input.track)) summary.warnings.push_back(std::move(warning));
  // The lab's start-up drive on the start poses, from several random placements: loud, for the
  // lab is where a failure costs a slot.
  const run_config::StartupDriveCheck drive = run_config::StartupDriveCheck::Of(config);
  if (!drive.AllSettled()) {
    summary.warnings.push_back("THE LAB WOULD LIKELY REJECT THIS RUN BEFORE STEP 0: " + drive.Message());
  }
  summary.instructions = Instructions(input, summary, params);
  nlohmann::ordered_json manifest = Manifest(input, summary, params, run_dir, controller_files.module_name);
  // The digest of every upload file, so that an edit after the export is
  // named (ExportedSubmission::Read) before check-submission or import trust it.
  nlohmann::ordered_json digests = nlohmann::ordered_json::object();
  for (const auto& [name, bytes] : upload_files) digests[name] = formats::Sha256::Hex(bytes);
  manifest[ExportedSubmission::kDigestsKey] = digests;

  files::OutputFolder out(out_dir);
  const files::OutputFolder upload(out.MakeSubfolder("upload"));  // refuses a link leading outside
  // Every file upload/ holds is this export's (UPLOAD.txt says to upload them all).
  upload.RemoveFiles("an earlier export's file");
  for (const auto& [name, bytes] : upload_files) upload.WriteFile(name, bytes);
  out.WriteFile("config.yaml", input.config_text);
  KeepControllerModule(config, out);
  out.WriteFile("export.json", files::JsonText(manifest) + "\n");
  out.WriteFile("UPLOAD.txt", summary.instructions);
  summary.out_dir = out.dir();
  summary.upload_dir = upload.dir();
  return summary;
}

}  // namespace dream::bridge
