#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dream/formats/npy_file.h"
#include "dream/bridge/run_track.h"
#include "dream/bridge/submission_params.h"
#include "dream/node/run_outcome.h"
#include "dream/run_config/run_config.h"
#include "dream/world/lab_verifier_rules.h"
#include "dream/world/run_judgement.h"
#include "dream/world/run_verdict.h"
#include "dream/world/verdict_reason.h"
#include "dream/world/violation_counts.h"
#include "dream/world/world.h"

namespace dream::bridge {

/// An export folder as `dream export` wrote it, read back for an import.
struct ExportedSubmission {
  std::string dir;
  SubmissionParams params;       ///< upload/dream_params.npy
  run_config::RunConfig config;  ///< config.yaml (a copy of the run's)
  std::string config_text;
  std::string source_run;  ///< the simulated run it came from (export.json), may be empty
  /// Whether export.json held the upload files' digests and every file
  /// matched; false only for an export written before digests were.
  bool digests_checked = false;

  /// export.json's key for the SHA-256 of each file in upload/, by name.
  static constexpr const char* kDigestsKey = "upload_sha256";

  /// @throws std::runtime_error naming the file when something is missing,
  ///         the parameters do not match the config, or a file in upload/ is
  ///         not as the export wrote it (its digest differs, it is missing,
  ///         or the export wrote no such file).
  static ExportedSubmission Read(const std::string& dir);

  /// The most values a result of this export can hold: every settle step,
  /// every experiment step and the final pose, of (3 + 5 N) columns.
  int64_t MaxResultValues() const;

  /// What UPLOAD.txt told the user to declare with this submission, from
  /// dream_params.npy and the config: its robot count, and (experiment steps
  /// + settle steps) x the time step.
  world::LabVerifierRules::Declaration UploadDeclaration() const;
};

/// A lab run as the submission script saved it, checked and turned into a
/// RunTrack: experiment step 0 is the first pose after the settle phase,
/// times are the lab's wall clock since then.
struct LabResult {
  RunTrack track;
  int64_t settle_steps = 0;   ///< iterations the script spent settling
  int64_t planned_steps = 0;  ///< steps the export planned
  int64_t iterations = 0;     ///< step() calls the script made (settle + experiment rows): the verifier's count
  bool complete = false;  ///< the final pose is there: every planned step, or (controller strategy) every robot done
  double wall_duration_s = 0.0;  ///< wall time from step 0 to the last pose
  double max_step_s = 0.0;       ///< longest wall time between two steps
  int64_t clock_steps_back = 0;  ///< stamps earlier than their predecessor (clamped)
};

/// The rows of a result file: dream_result.npy, or a .mat file holding the
/// same matrix as variable `dream_result` (chosen by the file's first bytes);
/// a .mat variable declaring more than `max_values` values is refused before
/// anything is allocated for them (a .npy's shape must match its bytes).
/// @throws std::runtime_error naming the file.
formats::NpyArray ReadResultFile(const std::string& path, int64_t max_values = int64_t{1} << 26);

/// Checks the rows strictly against the export (column count for its robot
/// count, phases and steps in order, no more steps than planned, every value
/// finite) and builds the track, with the virtual obstacles of the config at
/// each step. A run cut short (the lab stopped it) is accepted with
/// complete = false; it needs at least two experiment steps.
/// @throws std::runtime_error "<name>: <problem>" naming row, column and robot.
LabResult ParseLabResult(const formats::NpyArray& rows, const std::string& name, const ExportedSubmission& exported);

/// The lab verifier's rules (world::LabVerifierRules) on a lab run: its robot
/// count and step() calls (settle and experiment) against `declared`, robots
/// too close or outside the arena counted on its poses. One kRejected reason
/// per broken rule, naming the measured and the declared value; empty when
/// the verifier would pass it.
std::vector<world::VerdictReason> LabVerifierReasons(const LabResult& lab, const world::WorldParams& world,
                                                     const world::LabVerifierRules::Declaration& declared);

/// What ImportLabRun wrote and what the run's report needs: the world
/// stepped over the lab's poses, how the run ended and its judgement as a lab
/// run. summary.json and trajectories.png are the caller's to write, with
/// the one writer of run reports (session::RunReporter, through
/// workflows::ImportWorkflow), which adds the experiment's metrics and goal.
struct ImportedRun {
  LabResult lab;
  run_config::RunConfig config;  ///< the export's copy of the run's config
  world::ViolationCounts violations{};
  world::LabVerifierRules::Declaration declared;  ///< what the run was judged against
  /// Judged as a lab run: the Robotarium's checks on the lab's poses, the
  /// verifier's rules (LabVerifierReasons), a cut-short run (not
  /// node::JudgeRun's, which assumes the run is its own export). The goal is
  /// the report's to add.
  world::RunJudgement judgement{world::RunReport{}};
  std::shared_ptr<const world::World> world;  ///< a LabReplayWorld at the lab run's last step
  node::RunOutcome outcome;
  /// summary.json's "lab" section: the files, the strategy, the steps, what was declared, the lab's clock.
  nlohmann::ordered_json lab_json;
  std::string log_path;
  /// judgement's verdict and reasons.
  world::RunVerdict verdict() const { return judgement.verdict(); }
  const std::vector<world::VerdictReason>& verdict_reasons() const { return judgement.reasons(); }
};

/// `dream import`'s lab part: reads the lab's result file (.npy or .mat) for
/// the export in `export_dir` and writes, in `out_dir`, the run's log as
/// `dream run` writes it: run.lcmlog (the same channels and types:
/// DREAM_OBSTACLES, DREAM_STATUS, DREAM_POSES at the lab's timestamps, the
/// commands as sent on DREAM_CMD_<id>), and config.yaml (with the
/// controller's module). The judgement holds the run to `declared` (what the
/// user declared on the lab's form; absent: what UPLOAD.txt said,
/// UploadDeclaration()). Nothing is written unless the result file passes
/// every check; each file is written atomically; the folder stays locked
/// until the process exits. @throws std::runtime_error naming the file.
ImportedRun ImportLabRun(const std::string& result_path, const std::string& export_dir, const std::string& out_dir,
                         const std::optional<world::LabVerifierRules::Declaration>& declared = {});

/// The same for an export described in memory (`exported`: a Robotarium
/// script's export, whose run config and plan are made from its result:
/// workflows::ScriptLabSubmission).
ImportedRun ImportLabRun(const std::string& result_path, const ExportedSubmission& exported, const std::string& out_dir,
                         const std::optional<world::LabVerifierRules::Declaration>& declared = {});

/// Writes `track` as a run log (see ImportLabRun) to `log_path` atomically
/// and returns the violations counted on it. `end_state` and `detail` go in
/// the final DREAM_STATUS.
world::ViolationCounts WriteLabRunLog(const RunTrack& track, const world::WorldParams& world, int8_t end_state,
                                      const std::string& detail, const std::string& log_path);

}  // namespace dream::bridge
