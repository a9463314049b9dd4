// dream export / import / lab-replay / compare / check-submission: the bridge
// to the Robotarium (docs/robotarium.md). The work is in dream::bridge; this
// file is options, messages and exit codes.
#include <spdlog/spdlog.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hosted_agents.h"
#include "command_line.h"
#include "calibration_export.h"
#include "commands.h"
#include "run_output.h"
#include "dream/session/run_session.h"
#include "dream/files/file_text.h"
#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/bridge/command_agreement.h"
#include "dream/bridge/lab_import.h"
#include "dream/bridge/lab_replay_world.h"
#include "dream/bridge/metrics_json.h"
#include "dream/files/json_text.h"
#include "dream/files/output_folder.h"
#include "dream/bridge/run_comparison.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/bridge/submission_format.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/world/run_report.h"
#include "dream/node/run_summary.h"
#include "dream/render/trajectory_picture.h"
#include "data_files.h"
#include "process_group.h"
#include "run_folder_choice.h"
#include "shared_options.h"

#ifndef DREAM_DEFAULT_PYTHON
#define DREAM_DEFAULT_PYTHON "/usr/bin/python3"
#endif

namespace dream::cli {
namespace {

namespace fs = std::filesystem;

std::string Cm(double m) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f cm", m * 100.0);
  return text;
}

/// dream_result.npy (or .mat) in `path` when it is a folder, else `path`.
std::string ResultFile(const std::string& path) {
  if (!fs::is_directory(path)) return path;
  for (const char* name : {bridge::SubmissionFiles::kResult, bridge::SubmissionFiles::kResultMat}) {
    const fs::path candidate = fs::path(path) / name;
    if (fs::exists(candidate)) return candidate.string();
  }
  throw std::runtime_error(path + ": holds neither " + std::string(bridge::SubmissionFiles::kResult) + " nor " +
                           bridge::SubmissionFiles::kResultMat + "; pass the file the lab returned");
}

void PrintImported(const bridge::ImportedRun& imported) {
  const bridge::LabResult& lab = imported.lab;
  const world::RunReport report = world::RunReport::FromViolations(lab.track.last_step(), imported.violations);
  std::cout << "imported " << lab.track.last_step() << " of " << lab.planned_steps << " planned steps of "
            << lab.track.num_robots << " robots (" << (lab.complete ? "complete" : "CUT SHORT") << "), after "
            << lab.settle_steps << " settle steps; " << lab.wall_duration_s << " s of lab time\n";
  if (lab.clock_steps_back > 0) {
    std::cout << "note: the lab's clock went back " << lab.clock_steps_back << " times; those stamps were held\n";
  }
  std::cout << "violations on the lab's poses: " << world::RunVerdictName(report.verdict) << " (boundary "
            << imported.violations.boundary_errors << ", collision " << imported.violations.collision_errors
            << ", actuator " << imported.violations.actuator_errors << ", obstacle "
            << imported.violations.obstacle_collisions << ")\n";
  std::cout << "log:     " << imported.log_path << "\nsummary: " << imported.summary_path
            << "\npicture: " << imported.picture_path << "\n";
}

}  // namespace

int RunExport(const ExportArgs& args) {
  bridge::ExportOptions options;
  options.barriers = args.barriers;
  options.settle_max_steps = args.settle_steps;
  options.force = args.force;
  options.python_runtime_dir = DataFiles::PythonRuntimeDir();
  if (args.calibration) return RunCalibrationExport(args, options);
  if (args.robots != 0) {
    throw std::runtime_error("--robots " + std::to_string(args.robots) +
                             ": goes with --calibration (an exported run has its config's robots)");
  }
  if (args.run_dir.empty()) {
    throw std::runtime_error("pass the run folder to export (dream export RUN), or --calibration --robots N");
  }
  options.strategy = bridge::ParseStrategy(args.strategy.empty() ? "track" : args.strategy);
  const std::string config_path =
      args.config_path.empty() ? (fs::path(args.run_dir) / "config.yaml").string() : args.config_path;
  std::string out_dir = args.out_dir;
  if (out_dir.empty()) {
    const run_config::RunConfig config = run_config::LoadRunConfigFile(config_path);
    std::error_code error;
    fs::create_directories("exports", error);
    out_dir = (fs::path("exports") / config.name).string();
  }
  try {
    const bridge::ExportSummary summary = bridge::ExportSubmission(args.run_dir, out_dir, options, args.config_path);
    std::cout << summary.instructions << "\nwritten: " << summary.out_dir << "/UPLOAD.txt, " << summary.upload_dir
              << "/ (" << summary.uploads.size() << " files)\n";
    return kExitOk;
  } catch (const bridge::ExportRefused& refused) {
    std::cerr << "dream export: " << refused.what() << "\nnothing was written.\n";
    return kExitRejected;
  }
}

int RunImport(const ImportArgs& args) {
  const bridge::ExportedSubmission exported = bridge::ExportedSubmission::Read(args.export_dir);
  const std::string out_dir =
      RunFolderChoice(args.out_dir, "runs/" + exported.config.name + "_lab", args.overwrite,
                      RunFolderChoice::Create::kLater)  // a refused result must leave no folder
          .dir();
  // What was declared on the lab's form: UPLOAD.txt's values unless told otherwise.
  std::optional<world::LabVerifierRules::Declaration> declared;
  if (args.declared_robots > 0 || args.declared_duration_s > 0) {
    declared = exported.UploadDeclaration();
    if (args.declared_robots > 0) declared->num_robots = args.declared_robots;
    if (args.declared_duration_s > 0) declared->duration_s = args.declared_duration_s;
  }
  const bridge::ImportedRun imported =
      bridge::ImportLabRun(ResultFile(args.result), args.export_dir, out_dir, declared);
  PrintImported(imported);
  std::cout << "verdict: " << world::RunVerdictName(imported.verdict) << " (declared " << imported.declared.num_robots
            << " robots, " << imported.declared.duration_s << " s; " << imported.lab.iterations << " iterations)\n";
  for (const world::VerdictReason& reason : imported.verdict_reasons) std::cout << "  - " << reason.Text() << "\n";
  // As dream run's exit codes; a run the lab cut short did not finish.
  if (!imported.lab.complete) return kExitRunFailed;
  switch (imported.verdict) {
    case world::RunVerdict::kRejected: return kExitRejected;
    case world::RunVerdict::kNotReady: return kExitNotReady;
    default: return kExitOk;
  }
}

int RunCompare(const CompareArgs& args) {
  const std::string out_dir = args.out_dir.empty() ? args.second_dir : args.out_dir;
  const bridge::RunComparison comparison = bridge::CompareRunsAndWrite(args.first_dir, args.second_dir, out_dir);
  std::cout << comparison.Text() << "\nwritten: " << out_dir << "/comparison.json, " << out_dir
            << "/comparison.png\n";
  return kExitOk;
}

/// What a lab replay gave: its exit code and, once the world has stepped,
/// how the agents' commands compare with the lab's.
struct LabReplayOutcome {
  int exit_code = kExitOk;
  std::optional<bridge::CommandAgreement> agreement;
};

/// dream lab-replay; `report` takes the verdict and the outputs' paths.
LabReplayOutcome ReplayLabRun(const LabReplayArgs& args, std::ostream* report) {
  const std::string log_in = (fs::path(args.lab_dir) / "run.lcmlog").string();
  const std::string config_in = (fs::path(args.lab_dir) / "config.yaml").string();
  run_config::RunConfig config = run_config::LoadRunConfigFile(config_in);
  bridge::RunTrack track = bridge::ReadRunTrack(log_in);
  if (track.num_robots != config.num_robots) {
    throw std::runtime_error(log_in + ": has " + std::to_string(track.num_robots) + " robots, " + config_in + " " +
                             std::to_string(config.num_robots));
  }
  if (track.last_step() < 1) throw std::runtime_error(log_in + ": the lab run has no step to replay");
  config.sim.max_steps = args.steps > 0 ? std::min<int64_t>(args.steps, track.last_step()) : track.last_step();
  config.sim.stop_when_done = false;  // the lab run is replayed to its end
  if (!args.mode.empty()) config.sim.mode = config::ParseWorldMode(args.mode);
  session::RunSession::Options options;
  options.steps_from_command_line = args.steps > 0;
  options.report = report;
  options.stop = &StopFlag();
  session::RunSession run(std::move(config), options);
  HostedAgents::Check(run.config(), run.factory(), run.config().sim.start_timeout_s);

  const std::string out_dir =
      RunFolderChoice(args.out_dir, "runs/" + run.config().name + "_lab_replay", args.overwrite).dir();
  const bool in_process = !args.world_only;
  lcm::LcmBus bus(args.lcm_url.empty() ? (in_process ? "memq://" : lcm::ResolveLcmUrl("")) : lcm::ResolveLcmUrl(args.lcm_url));
  std::unique_ptr<HostedAgents> host;
  if (in_process) {
    std::vector<int> ids(static_cast<size_t>(run.config().num_robots));
    std::iota(ids.begin(), ids.end(), 0);
    host = std::make_unique<HostedAgents>(
        bus, run.config(), ids, run.factory(),
        PythonHostProcess::Limits{run.config().sim.agent_timeout_s, run.config().sim.start_timeout_s, 0.0});
  }

  // The lab's poses, replayed as the world; what it adds to the summary: the
  // agents' commands beside the lab's, how differently the controller reacts
  // to the real poses than the lab script drove.
  const bridge::LabReplayWorld* replay = nullptr;
  session::RunSession::GivenWorld world;
  world.make = [&](node::RunRecorder& recorder) {
    auto made = std::make_unique<bridge::LabReplayWorld>(std::move(track), run.config().world, &recorder);
    replay = made.get();
    return made;
  };
  LabReplayOutcome outcome;
  world.summary_fields = [&](const world::World&) {
    outcome.agreement = bridge::CommandAgreement::Of(*replay);
    nlohmann::ordered_json fields;
    fields["config"] = "config.yaml";
    fields["lab_replay"] = {{"lab_run", fs::absolute(args.lab_dir).string()},
                            {"lab_command_channels", std::string(bridge::kLabCommandChannelPrefix) + "<id>"},
                            {"agents_vs_lab_commands", outcome.agreement->Json()}};
    return fields;
  };
  world.start_line = run.config().name + ": replaying " + std::to_string(run.config().sim.max_steps) +
                     " lab steps of " + std::to_string(run.config().num_robots) + " robots (" +
                     config::WorldModeName(run.config().sim.mode) + ") on " + bus.url() +
                     (in_process ? " with the agents in this process" : "; start the agents with dream agent");
  // The same recording, summary, verdict, report and picture as every run.
  outcome.exit_code = ExitCodeFor(run.Run(bus, {out_dir, files::ReadFileText(config_in)}, world));
  return outcome;
}

int RunLabReplay(const LabReplayArgs& args) { return ReplayLabRun(args, &std::cout).exit_code; }

/// A controller-strategy submission ran the controllers themselves: replays
/// the imported run against the same controllers as agents (dream lab-replay,
/// into `check_dir`/lab_replay) and says whether they sent what the
/// submission sent. Returns check.json's `controllers_on_lab_poses`.
nlohmann::ordered_json CheckControllersOnLabPoses(const files::OutputFolder& check_dir, LabReplayOutcome* outcome) {
  LabReplayArgs replay;
  replay.lab_dir = check_dir.dir();
  replay.out_dir = check_dir.PathOf("lab_replay");
  replay.overwrite = true;  // the check's own folder: a new check replaces it
  nlohmann::ordered_json json;
  json["replay"] = fs::absolute(replay.out_dir).string();
  std::cout << "\nreplaying the lab's poses against your controllers as agents (dream lab-replay)\n";
  try {
    std::ostream quiet(nullptr);  // the replay's own verdict would repeat the check's
    *outcome = ReplayLabRun(replay, &quiet);
  } catch (const std::exception& error) {
    std::cout << "WARNING: not replayed: " << error.what() << "\n";
    json["replayed"] = false;
    json["error"] = error.what();
    return json;
  }
  if (!outcome->agreement) {
    std::cout << "WARNING: the replay ended before its first step (" << replay.out_dir << ")\n";
    json["replayed"] = false;
    return json;
  }
  const bridge::CommandAgreement& agreement = *outcome->agreement;
  json["replayed"] = true;
  json["steps"] = agreement.steps();
  json["same_commands"] = agreement.Same();
  json["tolerance"] = bridge::CommandAgreement::kSameTolerance;
  const double max_v = agreement.MaxVDifference();
  const double max_w = agreement.MaxWDifference();
  json["max_v_difference_mps"] = max_v;
  json["max_w_difference_radps"] = max_w;
  char largest[96];
  std::snprintf(largest, sizeof(largest), "largest difference %.2g m/s, %.2g rad/s", max_v, max_w);
  if (agreement.Same()) {
    std::cout << "your controllers on the lab's poses send what the submission sent (" << largest << " over "
              << agreement.steps() << " steps):\nwhat differs from the simulated run comes from the poses the lab "
                 "gave them (the start-up drive leaves up to 5 mm), not from the controllers\n";
  } else {
    const auto& worst = agreement.robots()[static_cast<size_t>(agreement.WorstRobot())];
    std::cout << "WARNING: your controllers decided differently on the lab's poses than in the submission: robot "
              << worst.robot << " from step " << worst.first_different_step << " (" << largest
              << ").\nA controller that reads the clock or draws unseeded random numbers cannot be reproduced, and\n"
                 "an upload/ changed by hand after the export is not what the replay runs (the export's copy):\n"
                 "the simulated run then says little about the lab's. Per robot: "
              << replay.out_dir << "/summary.json (lab_replay)\n";
  }
  nlohmann::ordered_json silent = nlohmann::ordered_json::array();
  for (const auto& robot : agreement.robots()) {
    if (robot.v_mps.count() == agreement.steps()) continue;
    silent.push_back({{"robot", robot.robot}, {"steps_without_command", agreement.steps() - robot.v_mps.count()}});
    std::cout << "robot " << robot.robot << " sent no command at " << agreement.steps() - robot.v_mps.count()
              << " of " << agreement.steps() << " replayed steps (its controller failed or its agent was lost)\n";
  }
  json["robots_without_commands"] = silent;
  return json;
}

int RunCheckSubmission(const CheckSubmissionArgs& args) {
  // Refuses an upload/ edited after the export, naming the file.
  const bridge::ExportedSubmission exported = bridge::ExportedSubmission::Read(args.export_dir);
  if (!exported.digests_checked) {
    std::cout << "WARNING: " << args.export_dir << "/export.json has no digests of the upload files (an export "
              << "from before they were written): an edit of upload/ cannot be found; export the run again\n";
  }
  // The runner's rule for a simulator checkout, checked here so that a wrong
  // one is named before an output folder is made (it used to exit 4 after).
  // With --standin the runner looks at neither.
  std::string simulator_dir = args.standin ? std::string() : args.simulator;
  std::string simulator_named = "--simulator " + args.simulator;
  if (const char* env = std::getenv("ROBOTARIUM_PYTHON_SIMULATOR");
      simulator_dir.empty() && !args.standin && env != nullptr && *env != '\0') {
    simulator_dir = env;
    simulator_named = "$ROBOTARIUM_PYTHON_SIMULATOR " + simulator_dir;
  }
  if (!simulator_dir.empty() && !fs::is_directory(simulator_dir)) {
    throw std::runtime_error(simulator_named +
                             ": no such folder; pass a checkout of robotarium_python_simulator, or leave it out");
  }
  if (!simulator_dir.empty() && !fs::is_regular_file(fs::path(simulator_dir) / "rps" / "robotarium.py")) {
    throw std::runtime_error(simulator_named + ": has no rps/robotarium.py, so it is no checkout of "
                             "robotarium/robotarium_python_simulator (git clone it, or leave it out)");
  }
  const std::string run_dir = args.run_dir.empty() ? exported.source_run : args.run_dir;
  std::error_code same_error;
  if (!args.out_dir.empty() && !run_dir.empty() && fs::equivalent(args.out_dir, run_dir, same_error)) {
    throw std::runtime_error("--out " + args.out_dir + " is the simulated run the check compares with (" + run_dir +
                             "); the imported lab run would replace it: choose another --out");
  }
  // Chosen and locked before the script runs: a second check into the same
  // folder is refused before it can write lab_files/.
  const files::OutputFolder out(
      RunFolderChoice(args.out_dir, "runs/" + exported.config.name + "_check", args.overwrite).dir());
  const std::string workdir = out.MakeSubfolder("lab_files");
  const std::string report_path = out.PathOf("check_report.json");
  // An earlier check's files: lab_files/ must hold this upload only (a file
  // the new upload lacks would still be found there, and a broken upload
  // pass), and an earlier controller check's replay must not pass for this one's.
  files::OutputFolder(workdir).RemoveFiles("an earlier check's file");
  if (RunFolderChoice::HoldsRun(out.PathOf("lab_replay"))) {
    std::error_code error;
    fs::remove_all(out.PathOf("lab_replay"), error);
    if (error) throw std::runtime_error(out.PathOf("lab_replay") + ": cannot remove an earlier check's replay: " + error.message());
  }
  std::vector<std::string> argv = {args.python.empty() ? DREAM_DEFAULT_PYTHON : args.python,
                                   DataFiles::BridgePythonDir() + "/run_submission.py",
                                   "--upload", (fs::path(args.export_dir) / "upload").string(),
                                   "--workdir", workdir,
                                   "--report", report_path};
  if (args.standin) argv.push_back("--standin");
  if (!args.simulator.empty()) argv.insert(argv.end(), {"--simulator", args.simulator});
  if (args.require_official) argv.push_back("--require-official");
  if (args.skip_initialization) argv.push_back("--skip-initialization");
  spdlog::info("running {}/upload/{} in a Robotarium simulator (output in {})", args.export_dir,
               bridge::SubmissionFiles::kMainScript, workdir);
  int code = 0;
  {
    ProcessGroup group;
    const pid_t pid = group.Start(argv);
    code = group.WaitPassingOnStop(pid, StopFlag(), SIGINT);
  }
  if (StopFlag().load()) {
    std::cerr << "dream check-submission: interrupted while the script ran (its output so far: " << workdir
              << "/stdout.txt)\n";
    return kExitInterrupted;
  }
  if (code == 5) {
    std::cerr << "dream check-submission: no official Robotarium simulator found (--simulator DIR, "
                 "$ROBOTARIUM_PYTHON_SIMULATOR, or pip install it); leave out --require-official to use the "
                 "stand-in\n";
    return kExitInputError;
  }
  if (!fs::exists(report_path)) {
    std::cerr << "dream check-submission: the runner failed (exit " << code << ") before writing its report\n";
    return kExitRunFailed;
  }
  const nlohmann::json report = nlohmann::json::parse(files::ReadFileText(report_path));
  const std::string simulator = report.value("simulator", "?");
  const std::string verdict = report.value("verdict", "unknown");
  const std::vector<std::string> warnings = report.value("warnings", std::vector<std::string>{});
  std::cout << "simulator: " << (simulator == "official" ? "the official Robotarium simulator (" +
                                                               report.value("simulator_path", std::string()) + ")"
                                                         : std::string("DREAM's stand-in (the official one was not found)"))
            << "\n";
  if (!report.value("ok", false)) {
    std::cerr << "dream check-submission: the script failed in the simulator:\n"
              << report.value("error", std::string()) << "\n(its output: " << workdir << "/stdout.txt)\n";
    return report.value("startup_timeout", false) ? kExitRejected : kExitRunFailed;
  }
  std::cout << "debug() says:\n" << report.value("debug_text", std::string());
  for (const std::string& warning : warnings) std::cout << "WARNING (Python): " << warning << "\n";

  const bridge::ImportedRun imported = bridge::ImportLabRun(
      (fs::path(workdir) / bridge::SubmissionFiles::kResult).string(), args.export_dir, out.dir());
  PrintImported(imported);

  nlohmann::ordered_json check;
  check["simulator"] = simulator;
  check["simulator_path"] = report.value("simulator_path", std::string());
  check["script_ok"] = true;
  check["verdict"] = verdict;
  check["python_warnings"] = warnings;
  check["debug_text"] = report.value("debug_text", std::string());
  check["settle_steps"] = imported.lab.settle_steps;
  check["complete"] = imported.lab.complete;
  if (!run_dir.empty() && fs::exists(fs::path(run_dir) / "run.lcmlog")) {
    const bridge::RunComparison comparison = bridge::CompareRunsAndWrite(run_dir, out.dir(), out.dir());
    std::cout << "\n" << comparison.Text();
    std::cout << "tracking error against " << run_dir << ": RMS " << Cm(comparison.position_m.Rms()) << ", max "
              << Cm(comparison.position_m.max()) << "\n";
    check["compared_with"] = run_dir;
    check["tracking_rms_m"] = comparison.position_m.Rms();
    check["tracking_max_m"] = comparison.position_m.max();
  } else {
    std::cout << "\nnot compared: the simulated run " << (run_dir.empty() ? "(unknown)" : run_dir)
              << " is not there (pass --run DIR)\n";
  }
  LabReplayOutcome replayed;
  if (exported.params.options.strategy == bridge::Strategy::kController) {
    check["controllers_on_lab_poses"] = CheckControllersOnLabPoses(out, &replayed);
  }
  out.WriteFile("check.json", files::JsonText(check) + "\n");
  std::cout << "written: " << out.PathOf("check.json") << "\n";
  if (verdict == "rejected") return kExitRejected;
  if (verdict != "clean" || !warnings.empty()) {
    std::cout << "WARNING: the script ran, but with " << (verdict != "clean" ? "debug() warnings" : "Python warnings")
              << "; see above\n";
  }
  if (replayed.exit_code == kExitInterrupted) return kExitInterrupted;
  if (!imported.lab.complete) return kExitRunFailed;
  return replayed.agreement && !replayed.agreement->Same() ? kExitNotReady : kExitOk;
}

void DeclareBridgeCommands(CommandLine& line) {
  const auto [export_command, export_args] = line.AddCommand<ExportArgs>(
      "export",
      "Turn a recorded run into a Robotarium submission (a main script plus .npy data, and for\n"
      "--strategy controller the Python controller and DREAM's runtime), after checking it as the\n"
      "lab would: robots, duration, start poses, boundary and collision errors.\n"
      "With --calibration --robots N it first runs the calibration drive on N robots (the run behind\n"
      "dream calibrate) and exports that: one upload gives your lab's model.\n"
      "Example: dream export runs/go_to_goal --out exports/go_to_goal\n"
      "         dream export --calibration --robots 8",
      RunExport);
  export_command->add_option("run", export_args->run_dir,
                             "Run folder written by dream run (run.lcmlog, config.yaml); with --calibration,\n"
                             "the folder its run goes into (default runs/calibration_N)");
  export_command->add_option("--out", export_args->out_dir, "Output folder (default exports/<name>)");
  export_command->add_option("--config", export_args->config_path, "The run's config (default <run>/config.yaml)");
  export_command->add_option("--strategy", export_args->strategy,
                             "track: recorded commands plus feedback on the pose error; replay: open loop;\n"
                             "controller: the run's Python controller itself, every step on the lab's poses\n"
                             "(default track; --calibration: replay)")
      ->check(CLI::IsMember(bridge::StrategyNames()));
  export_command->add_flag("--calibration", export_args->calibration,
                           "Run the calibration drive (config/calibration.yaml's program) on --robots robots in the\n"
                           "ideal simulator, then export it open loop (replay); the lab's result, imported, is what\n"
                           "dream calibrate fits (docs/robotarium.md)");
  export_command->add_option("--robots", export_args->robots, "With --calibration: how many robots, 1 to 20");
  export_command->add_flag("--force", export_args->force,
                           "Export although the run is not ready: robots lost at its end (a controller failed or an\n"
                           "agent fell silent) or its experiment's goal missed; those problems are printed as warnings");
  export_command->add_flag("--barriers", export_args->barriers,
                           "Pass commands through the Robotarium's barrier certificates (safety layer)");
  export_command->add_option("--settle-steps", export_args->settle_steps,
                             "At most this many steps to settle on the start poses before step 0")
      ->check(CLI::Range(0, 3000))
      ->capture_default_str();

  const auto [import_command, import_args] = line.AddCommand<ImportArgs>(
      "import",
      "Turn what the lab returned (dream_result.npy, or dream_result.mat from MATLAB) into a run\n"
      "folder like dream run writes: run.lcmlog, summary.json, trajectories.png. Its verdict holds the\n"
      "run to the lab verifier's rules against what UPLOAD.txt said to declare (robot count, duration),\n"
      "or what --declared-robots / --declared-duration say was declared.\n"
      "Example: dream import ~/Downloads/dream_result.npy --export exports/go_to_goal --out runs/lab1",
      RunImport);
  import_command->add_option("result", import_args->result, "dream_result.npy / .mat, or a folder holding one")
      ->required();
  import_command->add_option("--export", import_args->export_dir, "The folder dream export wrote")->required();
  AddRunFolderOptions(import_command, &import_args->out_dir, &import_args->overwrite, "runs/<name>_lab");
  import_command->add_option("--declared-robots", import_args->declared_robots,
                             "The robot count declared on the lab's form, when not UPLOAD.txt's;\n"
                             "the verdict names a mismatch (verifier_robot_count)")
      ->check(CLI::Range(1, 1000));
  import_command->add_option("--declared-duration", import_args->declared_duration_s,
                             "The duration (s) declared on the lab's form, when not UPLOAD.txt's; the verdict\n"
                             "names a run over 1.5x of it (verifier_duration) or over 900 s (lab_duration_cap)")
      ->check(CLI::Range(0.001, 1e6));

  const auto [replay_command, replay_args] = line.AddCommand<LabReplayArgs>(
      "lab-replay",
      "Run a lab run (from dream import) as the world on the bus: the agents get the lab's poses\n"
      "and their commands are recorded beside the lab's. Agents run in this process (memq://)\n"
      "unless --world-only.\n"
      "Example: dream lab-replay runs/lab1 --out runs/lab1_replay",
      RunLabReplay);
  replay_command->add_option("lab", replay_args->lab_dir, "Run folder written by dream import")->required();
  AddRunFolderOptions(replay_command, &replay_args->out_dir, &replay_args->overwrite, "runs/<name>_lab_replay");
  replay_command->add_option("--lcm-url", replay_args->lcm_url,
                             "LCM URL (default memq://, or $LCM_DEFAULT_URL with --world-only)");
  replay_command->add_option("--steps", replay_args->steps, "Replay at most this many steps")->check(StepCount());
  replay_command->add_option("--mode", replay_args->mode, "Override the world mode")
      ->check(CLI::IsMember({"lockstep", "realtime"}));
  replay_command->add_flag("--world-only", replay_args->world_only,
                           "Only the world; start the agents elsewhere (dream agent CONFIG) on the same URL");

  const auto [compare_command, compare_args] = line.AddCommand<CompareArgs>(
      "compare",
      "Compare a simulated run with its lab run: tracking error per robot, closest approach,\n"
      "violations and the experiment's metrics side by side; writes comparison.json and .png.\n"
      "Example: dream compare runs/go_to_goal runs/lab1",
      RunCompare);
  compare_command->add_option("simulated", compare_args->first_dir, "The simulated run's folder")->required();
  compare_command->add_option("lab", compare_args->second_dir, "The lab run's folder (dream import)")->required();
  compare_command->add_option("--out", compare_args->out_dir, "Output folder (default: the lab run's folder)");

  const auto [check_command, check_args] = line.AddCommand<CheckSubmissionArgs>(
      "check-submission",
      "Run an exported submission in the official Robotarium Python simulator (or, when it is\n"
      "not installed, DREAM's stand-in), import what it saved and compare it with the run.\n"
      "Example: dream check-submission exports/go_to_goal --out runs/go_to_goal_check",
      RunCheckSubmission);
  check_command->add_option("export", check_args->export_dir, "The folder dream export wrote")->required();
  AddRunFolderOptions(check_command, &check_args->out_dir, &check_args->overwrite, "runs/<name>_check");
  check_command->add_option("--run", check_args->run_dir,
                            "The simulated run to compare with (default: the exported one)");
  check_command->add_option("--simulator", check_args->simulator,
                            "robotarium_python_simulator checkout (default $ROBOTARIUM_PYTHON_SIMULATOR)");
  check_command->add_option("--python", check_args->python, "Python with numpy (and what the simulator needs)");
  check_command->add_flag("--standin", check_args->standin, "Use DREAM's stand-in even if the official one is there");
  check_command->add_flag("--require-official", check_args->require_official,
                          "Fail (exit 1) instead of using the stand-in when the official simulator is missing");
  check_command->add_flag("--skip-initialization", check_args->skip_initialization,
                          "Start exactly at the start poses (no start-up drive)");
}

}  // namespace dream::cli
