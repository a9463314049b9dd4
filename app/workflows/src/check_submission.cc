#include "dream/workflows/check_submission.h"
#include "dream/workflows/lab_replay_workflow.h"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "dream/bridge/run_comparison.h"
#include "dream/bridge/submission_format.h"
#include "dream/files/file_text.h"
#include "dream/files/json_text.h"
#include "dream/node/run_summary.h"
#include "dream/session/experiment_goal.h"
#include "dream/world/run_verdict.h"
#include "dream/workflows/import_workflow.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

/// The runner's exit code when --require-official finds no official simulator.
constexpr int kRunnerNoOfficialSimulator = 5;

std::string Cm(double m) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f cm", m * 100.0);
  return text;
}

/// An earlier check's lab replay: removed so that it cannot pass for this
/// check's (a folder without a run's files is left alone).
void RemoveEarlierReplay(const std::string& dir) {
  std::error_code error;
  const bool holds_run = fs::exists(fs::path(dir) / "run.lcmlog", error) ||
                         fs::exists(fs::path(dir) / "summary.json", error) ||
                         fs::exists(fs::path(dir) / "run.lcmlog.part", error);
  if (!holds_run) return;
  fs::remove_all(dir, error);
  if (error) throw std::runtime_error(dir + ": cannot remove an earlier check's replay: " + error.message());
}

/// summary.json's goal of the imported run ({} when it cannot be read).
nlohmann::json GoalOf(const std::string& summary_path) {
  try {
    const nlohmann::json summary = nlohmann::json::parse(files::ReadFileText(summary_path));
    return summary.contains("goal") && summary["goal"].is_object() ? summary["goal"] : nlohmann::json::object();
  } catch (const std::exception& error) {
    spdlog::warn("{}: cannot read the imported run's goal: {}", summary_path, error.what());
    return nlohmann::json::object();
  }
}

}  // namespace

CheckSubmission::CheckSubmission(Options options, Tools tools, std::ostream& out)
    : options_(std::move(options)), tools_(std::move(tools)), out_(out) {
  if (!tools_.replay_lab) {
    tools_.replay_lab = [this](const std::string& lab_dir, const std::string& replay_dir) {
      LabReplayWorkflow::Options replay;
      replay.lab_dir = lab_dir;
      replay.out_dir = replay_dir;
      replay.overwrite = true;  // the check's own folder: a new check replaces it
      replay.python_runtime_dir = options_.python_runtime_dir;
      replay.stop = options_.stop;
      std::ostream quiet(nullptr);
      const LabReplayWorkflow::Result replayed = LabReplayWorkflow(quiet).Replay(replay);
      return Replay{replayed.exit_code == session::kExitInterrupted, replayed.agreement};
    };
  }
}

std::string CheckSubmission::SimulatorChecked() const {
  // The runner's rule for a simulator checkout, checked here so that a wrong
  // one is named before an output folder is made. With --standin the runner
  // looks at neither.
  if (options_.standin) return {};
  std::string dir = options_.simulator;
  std::string named = "--simulator " + options_.simulator;
  if (dir.empty() && !options_.simulator_from_environment.empty()) {
    dir = options_.simulator_from_environment;
    named = "$ROBOTARIUM_PYTHON_SIMULATOR " + dir;
  }
  if (!dir.empty() && !fs::is_directory(dir)) {
    throw std::runtime_error(named +
                             ": no such folder; pass a checkout of robotarium_python_simulator, or leave it out");
  }
  if (!dir.empty() && !fs::is_regular_file(fs::path(dir) / "rps" / "robotarium.py")) {
    throw std::runtime_error(named +
                             ": has no rps/robotarium.py, so it is no checkout of "
                             "robotarium/robotarium_python_simulator (git clone it, or leave it out)");
  }
  return dir;
}

std::vector<std::string> CheckSubmission::RunnerArgv(const std::string& workdir, const std::string& report_path,
                                                     const std::string& main_file) const {
  std::vector<std::string> argv = {options_.python, options_.runner_script,
                                   "--upload",      (fs::path(options_.export_dir) / "upload").string(),
                                   "--workdir",     workdir,
                                   "--report",      report_path};
  if (options_.standin) argv.push_back("--standin");
  if (!options_.simulator.empty()) argv.insert(argv.end(), {"--simulator", options_.simulator});
  if (options_.require_official) argv.push_back("--require-official");
  if (options_.skip_initialization) argv.push_back("--skip-initialization");
  // Real-time pacing changes no pose: a script's check runs as fast as it goes.
  if (!main_file.empty()) argv.insert(argv.end(), {"--main", main_file, "--no-pacing"});
  return argv;
}

/// Runs the runner; a Result when the check ends there, else its report.
std::optional<CheckSubmission::Result> CheckSubmission::RunRunner(const files::OutputFolder& out,
                                                                  const std::string& workdir, nlohmann::json* report,
                                                                  const std::string& main_file) const {
  const std::string report_path = out.PathOf(kReportName);
  spdlog::info("running {}/upload/{} in a Robotarium simulator (output in {})", options_.export_dir,
               main_file.empty() ? bridge::SubmissionFiles::kMainScript : main_file, workdir);
  const ScriptRun ran = tools_.run_script(RunnerArgv(workdir, report_path, main_file));
  Result ended;
  ended.dir = out.dir();
  if (ran.interrupted) {
    ended.outcome = Outcome::kInterrupted;
    ended.error = "interrupted while the script ran (its output so far: " + workdir + "/stdout.txt)";
    return ended;
  }
  if (ran.exit_code == kRunnerNoOfficialSimulator) {
    ended.outcome = Outcome::kNoOfficialSimulator;
    ended.error =
        "no official Robotarium simulator found (--simulator DIR, $ROBOTARIUM_PYTHON_SIMULATOR, or pip "
        "install it); leave out --require-official to use the stand-in";
    return ended;
  }
  if (!fs::exists(report_path)) {
    ended.outcome = Outcome::kRunnerFailed;
    ended.error = "the runner failed (exit " + std::to_string(ran.exit_code) + ") before writing its report";
    return ended;
  }
  try {
    *report = nlohmann::json::parse(files::ReadFileText(report_path));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(report_path + ": the runner's report is not valid JSON: " + e.what());
  }
  const std::string simulator = report->value("simulator", "?");
  // A newcomer who wanted the official simulator learns here how to name it.
  const std::string standin_why =
      options_.standin ? "--standin"
                       : "the official one was not found: --simulator DIR or $ROBOTARIUM_PYTHON_SIMULATOR";
  out_ << "simulator: "
       << (simulator == "official"
               ? "the official Robotarium simulator (" + report->value("simulator_path", std::string()) + ")"
               : "DREAM's stand-in (" + standin_why + ")")
       << "\n";
  if (!report->value("ok", false)) {
    ended.outcome = report->value("startup_timeout", false) ? Outcome::kStartupTimedOut : Outcome::kScriptFailed;
    ended.error = "the script failed in the simulator:\n" + report->value("error", std::string()) +
                  "\n(its output: " + workdir + "/stdout.txt)";
    return ended;
  }
  return std::nullopt;
}

void CheckSubmission::CompareWithRun(const std::string& run_dir, const std::string& dir,
                                     nlohmann::ordered_json* check) const {
  if (run_dir.empty() || !fs::exists(fs::path(run_dir) / "run.lcmlog")) {
    out_ << "\nnot compared: the simulated run " << (run_dir.empty() ? "(unknown)" : run_dir)
         << " is not there (pass --run DIR)\n";
    return;
  }
  const bridge::RunComparison comparison = bridge::CompareRunsAndWrite(run_dir, dir, dir, options_.python_runtime_dir);
  out_ << "\n" << comparison.Text();
  out_ << "tracking error against " << run_dir << ": RMS " << Cm(comparison.position_m.Rms()) << ", max "
       << Cm(comparison.position_m.max()) << "\n";
  (*check)["compared_with"] = run_dir;
  (*check)["tracking_rms_m"] = comparison.position_m.Rms();
  (*check)["tracking_max_m"] = comparison.position_m.max();
}

CheckSubmission::Result CheckSubmission::Run() const {
  if (const std::optional<ScriptExport::Manifest> script = ScriptExport::Read(options_.export_dir)) {
    return RunScriptCheck(*script);
  }
  // Refuses an upload/ edited after the export, naming the file.
  const bridge::ExportedSubmission exported = bridge::ExportedSubmission::Read(options_.export_dir);
  if (!exported.digests_checked) {
    out_ << "WARNING: " << options_.export_dir << "/export.json has no digests of the upload files (an export "
         << "from before they were written): an edit of upload/ cannot be found; export the run again\n";
  }
  SimulatorChecked();
  const std::string run_dir = options_.run_dir.empty() ? exported.source_run : options_.run_dir;
  std::error_code same_error;
  if (!options_.out_dir.empty() && !run_dir.empty() && fs::equivalent(options_.out_dir, run_dir, same_error)) {
    throw std::runtime_error("--out " + options_.out_dir + " is the simulated run the check compares with (" + run_dir +
                             "); the imported lab run would replace it: choose another --out");
  }
  // Chosen and locked before the script runs: a second check into the same
  // folder is refused before it can write lab_files/.
  const files::OutputFolder out(
      tools_.choose_folder(options_.out_dir, "runs/" + exported.config.name + "_check", options_.overwrite));
  const std::string workdir = out.MakeSubfolder("lab_files");
  // An earlier check's files: lab_files/ must hold this upload only (a file
  // the new upload lacks would still be found there, and a broken upload
  // pass), and an earlier controller check's replay must not pass for this one's.
  files::OutputFolder(workdir).RemoveFiles("an earlier check's file");
  RemoveEarlierReplay(out.PathOf("lab_replay"));
  nlohmann::json report;
  if (std::optional<Result> ended = RunRunner(out, workdir, &report)) return *ended;
  const std::optional<world::RunVerdict> verdict = world::ParseRunVerdict(report.value("verdict", "unknown"));
  const std::vector<std::string> warnings = report.value("warnings", std::vector<std::string>{});
  PrintDebugReport(report, warnings);

  const ImportWorkflow::Result imported = ImportLabRun(out.dir(), workdir);
  // One verdict: the imported run judged as every run is (the lab verifier's
  // rules, the goal, the run's state), and no better than debug() said.
  const world::RunVerdict one_verdict = std::max(verdict.value_or(world::RunVerdict::kRejected), imported.verdict());
  const nlohmann::json goal = GoalOf(imported.summary_path);

  Result result;
  result.dir = out.dir();
  nlohmann::ordered_json& check = result.check;
  check["simulator"] = report.value("simulator", "?");
  check["simulator_path"] = report.value("simulator_path", std::string());
  check["script_ok"] = true;
  node::SetSummaryVerdict(&check, imported.report.judgement);  // the reasons, as summary.json has them
  check["verdict"] = world::RunVerdictName(one_verdict);
  check["debug_verdict"] = report.value("verdict", "unknown");
  check["goal"] = goal;
  check["python_warnings"] = warnings;
  check["debug_text"] = report.value("debug_text", std::string());
  check["settle_steps"] = imported.imported.lab.settle_steps;
  check["complete"] = imported.imported.lab.complete;
  CompareWithRun(run_dir, out.dir(), &check);
  Replay replayed;
  if (exported.params.options.strategy == bridge::Strategy::kController) {
    check["controllers_on_lab_poses"] = ControllersOnLabPoses(out, &replayed);
  }
  out.WriteFile("check.json", files::JsonText(check) + "\n");
  out_ << "written: " << out.PathOf("check.json") << "\n";
  if (one_verdict == world::RunVerdict::kRejected) {
    result.outcome = Outcome::kRejected;
    return result;
  }
  if (verdict != world::RunVerdict::kClean || !warnings.empty()) {
    out_ << "WARNING: the script ran, but with "
         << (verdict != world::RunVerdict::kClean ? "debug() warnings" : "Python warnings") << "; see above\n";
  }
  if (replayed.interrupted) {
    result.outcome = Outcome::kInterrupted;
  } else if (!imported.imported.lab.complete) {
    result.outcome = Outcome::kIncomplete;
  } else if (replayed.agreement && !replayed.agreement->Same()) {
    result.outcome = Outcome::kControllersDiffer;
  } else if (one_verdict == world::RunVerdict::kNotReady) {
    result.outcome = Outcome::kNotReady;
  }
  return result;
}

void CheckSubmission::PrintDebugReport(const nlohmann::json& report, const std::vector<std::string>& warnings) const {
  out_ << "debug() says:\n" << report.value("debug_text", std::string());
  // Its "took approximately 99.00 real seconds" is the lab's time, not this check's.
  out_ << "(debug()'s real seconds are the time on the lab's robots: iterations x 0.033 s)\n";
  for (const std::string& warning : warnings) out_ << "WARNING (Python): " << warning << "\n";
}

ImportWorkflow::Result CheckSubmission::ImportLabRun(const std::string& out_dir, const std::string& workdir) const {
  const ImportWorkflow importer(out_);
  ImportWorkflow::Options import;
  import.result = (fs::path(workdir) / bridge::SubmissionFiles::kResult).string();
  import.export_dir = options_.export_dir;
  import.out_dir = out_dir;
  import.python_runtime_dir = options_.python_runtime_dir;
  ImportWorkflow::Result imported = importer.Import(import);
  out_ << "\nthe lab run as dream import judges it:\n";
  importer.PrintVerdict(imported);
  out_ << "goal: " << session::ExperimentGoal::Text(GoalOf(imported.summary_path)) << "\n";
  return imported;
}

/// A controller-strategy submission ran the controllers themselves: replays
/// the imported run against the same controllers as agents (dream lab-replay,
/// into the check's lab_replay) and says whether they sent what the
/// submission sent. Returns check.json's `controllers_on_lab_poses`.
nlohmann::ordered_json CheckSubmission::ControllersOnLabPoses(const files::OutputFolder& out, Replay* replayed) const {
  const std::string replay_dir = out.PathOf("lab_replay");
  nlohmann::ordered_json json;
  json["replay"] = fs::absolute(replay_dir).string();
  out_ << "\nreplaying the lab's poses against your controllers as agents (dream lab-replay)\n";
  try {
    *replayed = tools_.replay_lab(out.dir(), replay_dir);
  } catch (const std::exception& error) {
    out_ << "WARNING: not replayed: " << error.what() << "\n";
    json["replayed"] = false;
    json["error"] = error.what();
    return json;
  }
  if (!replayed->agreement) {
    out_ << "WARNING: the replay ended before its first step (" << replay_dir << ")\n";
    json["replayed"] = false;
    return json;
  }
  const bridge::CommandAgreement& agreement = *replayed->agreement;
  json["replayed"] = true;
  json["steps"] = agreement.steps();
  json["same_commands"] = agreement.Same();
  json["tolerance"] = bridge::CommandAgreement::kSameTolerance;
  json["max_v_difference_mps"] = agreement.MaxVDifference();
  json["max_w_difference_radps"] = agreement.MaxWDifference();
  PrintAgreement(agreement, replay_dir);
  nlohmann::ordered_json silent = nlohmann::ordered_json::array();
  for (const auto& robot : agreement.robots()) {
    if (robot.v_mps.count() == agreement.steps()) continue;
    silent.push_back({{"robot", robot.robot}, {"steps_without_command", agreement.steps() - robot.v_mps.count()}});
    out_ << "robot " << robot.robot << " sent no command at " << agreement.steps() - robot.v_mps.count() << " of "
         << agreement.steps() << " replayed steps (its controller failed or its agent was lost)\n";
  }
  json["robots_without_commands"] = silent;
  return json;
}

void CheckSubmission::PrintAgreement(const bridge::CommandAgreement& agreement, const std::string& replay_dir) const {
  char largest[96];
  std::snprintf(largest, sizeof(largest), "largest difference %.2g m/s, %.2g rad/s", agreement.MaxVDifference(),
                agreement.MaxWDifference());
  if (agreement.Same()) {
    out_ << "your controllers on the lab's poses send what the submission sent (" << largest << " over "
         << agreement.steps()
         << " steps):\nwhat differs from the simulated run comes from the poses the lab "
            "gave them (the start-up drive leaves up to 5 mm), not from the controllers\n";
    return;
  }
  const auto& worst = agreement.robots()[static_cast<size_t>(agreement.WorstRobot())];
  out_ << "WARNING: your controllers decided differently on the lab's poses than in the submission: robot "
       << worst.robot << " from step " << worst.first_different_step << " (" << largest
       << ").\nA controller that reads the clock or draws unseeded random numbers cannot be reproduced, and\n"
          "an upload/ changed by hand after the export is not what the replay runs (the export's copy):\n"
          "the simulated run then says little about the lab's. Per robot: "
       << replay_dir << "/summary.json (lab_replay)\n";
}

}  // namespace dream::workflows
