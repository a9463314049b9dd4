#pragma once

#include <iostream>
#include <optional>
#include <ostream>
#include <string>

#include "dream/bridge/lab_import.h"
#include "dream/session/run_result.h"
#include "dream/world/lab_verifier_rules.h"
#include "dream/world/run_verdict.h"

namespace dream::workflows {

/// `dream import`: what the lab returned (dream_result.npy or .mat) becomes a
/// run folder like `dream run` writes. The lab part (the result checked, the
/// run log, the lab verifier's judgement) is bridge::ImportLabRun's; the
/// report (summary.json with the experiment's metrics and goal, the verdict
/// with the goal's reason, trajectories.png with the goals drawn) is the one
/// every run gets, session::RunReporter's, through a RunSession of the
/// export's config (the controller factory built once, there).
class ImportWorkflow {
 public:
  struct Options {
    std::string result;      ///< dream_result.npy / .mat, or a folder holding one (ResultFile)
    std::string export_dir;  ///< the folder dream export wrote
    std::string out_dir;     ///< the run folder to write (chosen by the caller; made when missing)
    /// What was declared on the lab's form; none: what UPLOAD.txt said.
    std::optional<world::LabVerifierRules::Declaration> declared;
    /// The Python runtime, so a Python controller's own goal judges the lab run too ("": not judged).
    std::string python_runtime_dir;
  };

  /// What `dream import` is asked, as typed.
  struct Asked {
    std::string result;  ///< dream_result.npy / .mat, or a folder holding one
    std::string export_dir;
    std::string out_dir;               ///< empty: runs/<name>_lab (or _2, ... when that holds a run)
    bool overwrite = false;            ///< replace a run already in the output folder
    int declared_robots = 0;           ///< declared on the lab's form; 0: the export's (UPLOAD.txt)
    double declared_duration_s = 0.0;  ///< declared on the lab's form; 0: the export's (UPLOAD.txt)
    std::string python_runtime_dir;
  };

  /// The Options `asked` means: the export read (its name gives the default
  /// folder, files::RunFolderChoice, made only when the import writes: a
  /// refused result leaves no folder) and what was declared on the lab's form,
  /// UPLOAD.txt's values unless told otherwise.
  static Options OptionsOf(const Asked& asked);

  /// The export `result` is a lab run of: what dream export wrote in
  /// `export_dir`, or, for a Robotarium script's export (ScriptExport), the
  /// one ScriptLabSubmission makes from the result.
  /// @throws std::runtime_error naming the file.
  static bridge::ExportedSubmission ExportOf(const std::string& export_dir, const std::string& result,
                                             const std::string& python_runtime_dir);

  /// What the import wrote and how the run was judged.
  struct Result {
    bridge::ImportedRun imported;
    session::RunResult report;  ///< the judgement with the goal, and whether summary.json and the picture were written
    std::string summary_path;
    std::string picture_path;  ///< empty when no picture was written
    world::RunVerdict verdict() const { return report.judgement.verdict(); }
  };

  /// `out` takes what the import prints: the lab run's steps, the verdict
  /// with its reasons and the outputs' paths.
  explicit ImportWorkflow(std::ostream& out = std::cout) : out_(out) {}

  /// @throws std::runtime_error naming the file, as bridge::ImportLabRun;
  ///         nothing is written when the result file is refused.
  Result Import(const Options& options) const;

  /// The declaration for `dream import --declared-robots/--declared-duration`:
  /// UPLOAD.txt's values with the given ones (> 0) in their place; none when
  /// neither is given.
  static std::optional<world::LabVerifierRules::Declaration> Declared(const bridge::ExportedSubmission& exported,
                                                                      int robots, double duration_s);

  /// dream_result.npy (or .mat) in `path` when it is a folder, else `path`.
  /// @throws std::runtime_error when the folder holds neither.
  static std::string ResultFile(const std::string& path);

  /// The lines `dream import` and `dream check-submission` print about an
  /// imported lab run: its steps, the lab's clock, the violations on its poses.
  void PrintLabRun(const bridge::ImportedRun& imported) const;
  /// The verdict (with the goal's), what it was judged against, and its reasons.
  void PrintVerdict(const Result& result) const;

  /// The exit code of an import, as dream run's (session::ExitCodeOf); a
  /// run the lab cut short did not finish, nor one whose report failed.
  static int ExitCodeOf(const Result& result);

 private:
  std::ostream& out_;
};

}  // namespace dream::workflows
