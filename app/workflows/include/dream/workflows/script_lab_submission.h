#pragma once

#include <string>

#include "dream/bridge/lab_import.h"

namespace dream::workflows {

/// A Robotarium script's export (ScriptExport) as `dream import` needs it: the
/// script was uploaded as it is, with DREAM's recorder as the main file
/// (dream_record.py), so the lab returns dream_result.npy in the form every
/// export's result has (docs/robotarium.md), but the export knows neither the
/// robots nor the start: both come from the result. Its first experiment row
/// gives the robots (the column count) and the start poses; the run config is
/// the one `dream run SCRIPT.py` makes for them (ScriptRunWorkflow::ConfigText,
/// naming the script); the plan is what the result holds (its settle rows, the
/// official start-up drive's, and its experiment rows: a final pose row after
/// them is a complete run, none a run the lab cut short), so what
/// UploadDeclaration() says is what the script took: the script's export
/// declares nothing else (--declared-robots, --declared-duration do).
class ScriptLabSubmission {
 public:
  /// @throws std::runtime_error naming the file: a result of no robot count,
  ///         with no experiment row, or start poses no run config takes.
  /// `goal_record` ("": none): the config's controller.goal_record, where
  /// the import puts the script's last check the recorder kept (CopyGoal).
  static bridge::ExportedSubmission Of(const std::string& export_dir, const std::string& result_path,
                                       const std::string& python_runtime_dir, const std::string& goal_record = "");

  /// The recorder's dream_goal.json beside `result_path` (the lab returns it
  /// with dream_result.npy), copied to `goal_record`; nothing when it is not
  /// there (the run then has no goal). @throws std::runtime_error naming the
  /// file when it is no regular file or over 1 MiB.
  static void CopyGoal(const std::string& result_path, const std::string& goal_record);

  /// The recorder's goal file's name (python/rps_dream/dream_record.py's GOAL).
  static constexpr const char* kRecorderGoalName = "dream_goal.json";
};

}  // namespace dream::workflows
