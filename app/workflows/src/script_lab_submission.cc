#include "dream/workflows/script_lab_submission.h"

#include <filesystem>
#include <stdexcept>

#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"

#include "dream/bridge/submission_format.h"
#include "dream/config/config_node.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/run_config/run_config.h"
#include "dream/workflows/script_export.h"
#include "dream/workflows/script_run_workflow.h"

namespace dream::workflows {
namespace {

using bridge::ResultLayout;

constexpr size_t kMaxGoalBytes = 1 << 20;  // 50 robots' targets take a few kB

/// The rows of the result, with its robot count and where its experiment starts.
struct ScriptResult {
  formats::NpyArray rows;
  int robots = 0;
  int64_t settle_rows = 0;
  int64_t experiment_rows = 0;

  explicit ScriptResult(const std::string& path) : rows(bridge::ReadResultFile(path)) {
    if (rows.shape.size() != 2) throw std::runtime_error(path + ": not a 2-D result");
    const int64_t columns = rows.shape[1];
    const int64_t robot_columns = columns - ResultLayout::kFixedColumns;
    if (robot_columns < 5 || robot_columns % 5 != 0 ||
        robot_columns / 5 > robotarium::RobotariumConstants::kMaxRobotsInSimulation) {
      throw std::runtime_error(path + ": " + std::to_string(columns) +
                               " columns are 3 + 5 N for no robot count N of 1..50: not a dream result");
    }
    robots = static_cast<int>(robot_columns / 5);
    for (int64_t r = 0; r < rows.shape[0]; ++r) {
      const double phase = rows.values[static_cast<size_t>(r * columns + ResultLayout::kPhaseColumn)];
      if (phase == ResultLayout::kPhaseSettle && experiment_rows == 0) ++settle_rows;
      if (phase == ResultLayout::kPhaseExperiment) ++experiment_rows;
    }
    if (experiment_rows == 0) {
      throw std::runtime_error(path +
                               ": no experiment row (phase 1): the script made no step() after its "
                               "Robotarium(...); see the lab's output");
    }
  }

  double At(int64_t row, int64_t column) const {
    return rows.values[static_cast<size_t>(row * rows.shape[1] + column)];
  }
};

}  // namespace

bridge::ExportedSubmission ScriptLabSubmission::Of(const std::string& export_dir, const std::string& result_path,
                                                   const std::string& python_runtime_dir,
                                                   const std::string& goal_record) {
  const std::optional<ScriptExport::Manifest> manifest = ScriptExport::Read(export_dir);
  if (!manifest)
    throw std::runtime_error(export_dir + ": no " + ScriptExport::kManifestName + ": not a script's export");
  const ScriptResult result(result_path);
  ScriptRunWorkflow::Hello hello;
  hello.robots = result.robots;
  hello.startup_steps = result.settle_rows;
  for (int i = 0; i < result.robots; ++i) {
    const int64_t row = result.settle_rows;  // the first experiment row: where the start-up drive left them
    hello.initial_poses.push_back({result.At(row, ResultLayout::X(result.robots, i)),
                                   result.At(row, ResultLayout::Y(result.robots, i)),
                                   result.At(row, ResultLayout::Theta(result.robots, i))});
  }
  ScriptRunWorkflow::Options options;
  options.script_path = manifest->script;
  options.python_runtime_dir = python_runtime_dir;
  bridge::ExportedSubmission exported;
  exported.dir = export_dir;
  exported.source_run = manifest->script;
  exported.config_text = ScriptRunWorkflow::ConfigText(hello, options, goal_record);
  exported.config = run_config::LoadRunConfig(
      config::ConfigNode::LoadString(exported.config_text, result_path + " (its run config, from its first poses)"));
  bridge::SubmissionParams& params = exported.params;
  params.num_robots = result.robots;
  params.steps = result.experiment_rows;                    // the script's own plan, as it ran
  params.options.strategy = bridge::Strategy::kController;  // the script itself, in closed loop on the lab
  params.options.settle_max_steps = static_cast<int>(result.settle_rows + 1);
  return exported;
}

void ScriptLabSubmission::CopyGoal(const std::string& result_path, const std::string& goal_record) {
  const std::filesystem::path from = std::filesystem::path(result_path).parent_path() / kRecorderGoalName;
  std::error_code error;
  if (!std::filesystem::exists(from, error)) return;
  files::WriteFileAtomically(goal_record, files::ReadFileText(from.string(), kMaxGoalBytes));
}

}  // namespace dream::workflows
