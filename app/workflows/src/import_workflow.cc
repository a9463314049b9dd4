#include "dream/workflows/import_workflow.h"

#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "dream/bridge/submission_format.h"
#include "dream/files/run_folder_choice.h"
#include "dream/session/exit_code.h"
#include "dream/session/run_exit_code.h"
#include "dream/session/run_reporter.h"
#include "dream/session/run_session.h"
#include "dream/session/verdict_broadcast.h"
#include "dream/workflows/script_export.h"
#include "dream/workflows/script_lab_submission.h"
#include "dream/workflows/script_run_workflow.h"
#include "dream/world/run_report.h"

namespace dream::workflows {
namespace {

// Durations to 0.01 s, as dream render and dream log info print them: "6.67 s", never "6.66667 s".
std::string SecondsText(double seconds) { return fmt::format("{:.2f} s", seconds); }

}  // namespace

namespace fs = std::filesystem;

std::string ImportWorkflow::ResultFile(const std::string& path) {
  if (!fs::is_directory(path)) return path;
  for (const char* name : {bridge::SubmissionFiles::kResult, bridge::SubmissionFiles::kResultMat}) {
    const fs::path candidate = fs::path(path) / name;
    if (fs::exists(candidate)) return candidate.string();
  }
  throw std::runtime_error(path + ": holds neither " + std::string(bridge::SubmissionFiles::kResult) + " nor " +
                           bridge::SubmissionFiles::kResultMat + "; pass the file the lab returned");
}

std::optional<world::LabVerifierRules::Declaration> ImportWorkflow::Declared(const bridge::ExportedSubmission& exported,
                                                                             int robots, double duration_s) {
  if (robots <= 0 && duration_s <= 0) return std::nullopt;
  world::LabVerifierRules::Declaration declared = exported.UploadDeclaration();
  if (robots > 0) declared.num_robots = robots;
  if (duration_s > 0) declared.duration_s = duration_s;
  return declared;
}

bridge::ExportedSubmission ImportWorkflow::ExportOf(const std::string& export_dir, const std::string& result,
                                                    const std::string& python_runtime_dir) {
  // A script's export: its run config and plan come from the result the recorder saved.
  if (ScriptExport::Read(export_dir))
    return ScriptLabSubmission::Of(export_dir, ResultFile(result), python_runtime_dir);
  return bridge::ExportedSubmission::Read(export_dir);
}

ImportWorkflow::Options ImportWorkflow::OptionsOf(const Asked& asked) {
  const bridge::ExportedSubmission exported = ExportOf(asked.export_dir, asked.result, asked.python_runtime_dir);
  Options options;
  options.result = asked.result;
  options.export_dir = asked.export_dir;
  options.out_dir = files::RunFolderChoice(asked.out_dir, "runs/" + exported.config.name + "_lab", asked.overwrite,
                                           files::RunFolderChoice::Create::kLater)
                        .dir();
  options.declared = Declared(exported, asked.declared_robots, asked.declared_duration_s);
  options.python_runtime_dir = asked.python_runtime_dir;
  return options;
}

int ImportWorkflow::ExitCodeOf(const Result& result) {
  if (!result.imported.lab.complete || !result.report.summary_written || result.report.picture_failed) {
    return session::kExitRunFailed;
  }
  return session::ExitCodeOf(result.verdict());
}

ImportWorkflow::Result ImportWorkflow::Import(const Options& options) const {
  Result result;
  const std::string result_file = ResultFile(options.result);
  // A script's run is judged by its last at_pose/at_position check, which the recorder kept beside the result.
  const std::string goal_record = (fs::absolute(options.out_dir) / ScriptRunWorkflow::kGoalRecordName).string();
  const bool script = ScriptExport::Read(options.export_dir).has_value();
  result.imported = bridge::ImportLabRun(
      result_file,
      script ? ScriptLabSubmission::Of(options.export_dir, result_file, options.python_runtime_dir, goal_record)
             : bridge::ExportedSubmission::Read(options.export_dir),
      options.out_dir, options.declared);
  if (script) ScriptLabSubmission::CopyGoal(result_file, goal_record);
  const bridge::ImportedRun& imported = result.imported;
  // The run's report, written as every run's is; what it prints is said below, as a lab run's.
  session::RunSession::Options session_options;
  std::ostream quiet(nullptr);
  session_options.report = &quiet;
  session_options.python_runtime_dir = options.python_runtime_dir;
  const session::RunSession session(imported.config, session_options);
  session::RunReporter::Ended ended;
  ended.world = imported.world.get();
  ended.outcome = imported.outcome;
  ++ended.outcome.log_events;  // DREAM_VERDICT, appended once summary.json is written
  ended.dir = fs::path(imported.log_path).parent_path().string();
  ended.judgement = imported.judgement;
  ended.fields["config"] = "config.yaml";
  ended.fields["lab"] = imported.lab_json;
  result.report = session.Reporter().Report(ended);
  result.summary_path = ended.dir + "/" + session::RunReporter::kSummaryName;
  // As every run's log: it ends on the one judge's verdict, so dream view of it ends on summary.json's.
  if (result.report.summary_written) {
    session::VerdictBroadcast::Record(
        session::VerdictBroadcast::MessageOf(result.report, imported.outcome.run_id, imported.world->utime(),
                                             static_cast<session::ExitCode>(ExitCodeOf(result))),
        imported.log_path, imported.outcome.log_events);
  }
  if (result.report.summary_written && !result.report.picture_failed &&
      fs::exists(ended.dir + "/" + session::RunReporter::kPictureName)) {
    result.picture_path = ended.dir + "/" + session::RunReporter::kPictureName;
  }
  PrintLabRun(imported);
  return result;
}

void ImportWorkflow::PrintLabRun(const bridge::ImportedRun& imported) const {
  const bridge::LabResult& lab = imported.lab;
  const world::RunReport report = world::RunReport::FromViolations(lab.track.last_step(), imported.violations);
  out_ << "imported " << lab.track.last_step() << " of " << lab.planned_steps << " planned steps of "
       << lab.track.num_robots << " robots (" << (lab.complete ? "complete" : "CUT SHORT") << "), after "
       << lab.settle_steps << " settle steps; " << SecondsText(lab.wall_duration_s) << " of lab time\n";
  if (lab.clock_steps_back > 0) {
    out_ << "note: the lab's clock went back " << lab.clock_steps_back << " times; those stamps were held\n";
  }
  out_ << "violations on the lab's poses: " << world::RunVerdictName(report.verdict) << " (boundary "
       << imported.violations.boundary_errors << ", collision " << imported.violations.collision_errors << ", actuator "
       << imported.violations.actuator_errors << ", obstacle " << imported.violations.obstacle_collisions << ")\n";
  const std::string dir = fs::path(imported.log_path).parent_path().string();
  out_ << "log:     " << imported.log_path << "\nsummary: " << dir << "/" << session::RunReporter::kSummaryName
       << "\npicture: " << dir << "/" << session::RunReporter::kPictureName << "\n";
}

void ImportWorkflow::PrintVerdict(const Result& result) const {
  const bridge::ImportedRun& imported = result.imported;
  out_ << "verdict: " << world::RunVerdictName(result.verdict()) << " (declared " << imported.declared.num_robots
       << " robots, " << SecondsText(imported.declared.duration_s) << "; " << imported.lab.iterations
       << " iterations)\n";
  for (const world::VerdictReason& reason : result.report.judgement.reasons()) out_ << "  - " << reason.Text() << "\n";
}

}  // namespace dream::workflows
