// ImportWorkflow: a lab run is reported as a simulated run is, by the same
// writer (session::RunReporter): summary.json with the experiment's metrics,
// its goal and the goal's verdict, a picture with the goals drawn.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../bridge/bridge_test_support.h"
#include "../support/source_tree.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/submission_format.h"
#include "dream/files/file_text.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/robot_poses_t.hpp"
#include "dream/run_config/run_config.h"
#include "dream/run_log/run_log.h"
#include "dream/run_verdict_t.hpp"
#include "dream/workflows/import_workflow.h"
#include "dream/workflows/lab_replay_workflow.h"
#include "dream/workflows/view_replay.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::ContainsRegex;
using ::testing::HasSubstr;

/// Writes `rows` as a lab result and imports it into `<folder>/out`.
ImportWorkflow::Result Import(const formats::NpyArray& rows, const std::string& name, std::ostream& out,
                              const std::optional<world::LabVerifierRules::Declaration>& declared = {}) {
  const std::string dir = bridge::testing::NewFolder("workflow_import_" + name);
  bridge::testing::WriteText(dir + "/" + bridge::SubmissionFiles::kResult, formats::EncodeNpy(rows));
  // A folder holding the result file stands for it.
  return ImportWorkflow(out).Import({dir, testing::SimulatedExport(), dir + "/out", declared, ""});
}

nlohmann::json ReadJson(const std::string& path) { return nlohmann::json::parse(files::ReadFileText(path)); }

TEST(ImportWorkflowTest, ALabRunsSummaryCarriesEverythingARunsSummaryDoes) {
  std::ostringstream out;
  const ImportWorkflow::Result result =
      Import(bridge::testing::PerfectLabResult(testing::SimulatedExport()), "perfect", out);
  const nlohmann::json run = ReadJson(testing::SimulatedRun() + "/summary.json");
  const nlohmann::json lab = ReadJson(result.summary_path);
  for (const auto& [key, value] : run.items()) EXPECT_TRUE(lab.contains(key)) << "the import's summary lacks " << key;
  // The goal a run is judged by, judged on the lab's poses (a perfect lab: as the run's).
  ASSERT_TRUE(lab.contains("goal"));
  EXPECT_EQ(lab["goal"], run["goal"]);
  EXPECT_EQ(lab["goal"]["judged"], true);
  EXPECT_EQ(lab["metrics"]["kind"], "go_to_goal");
  EXPECT_EQ(lab["verdict"], "clean");
  EXPECT_EQ(lab["config"], "config.yaml");
  EXPECT_EQ(lab["lab"]["complete"], true);
  EXPECT_EQ(lab["lab"]["declared_from"], "export");
  EXPECT_EQ(result.verdict(), world::RunVerdict::kClean);
  EXPECT_TRUE(result.report.summary_written);
  EXPECT_FALSE(result.report.picture_failed);
  EXPECT_EQ(result.picture_path, fs::path(result.summary_path).parent_path().string() + "/trajectories.png");
  EXPECT_TRUE(fs::exists(result.picture_path));
  EXPECT_THAT(out.str(), HasSubstr("imported "));
  // Durations to 0.01 s, never a raw float such as "6.66667 s".
  EXPECT_THAT(out.str(), ContainsRegex(" settle steps; [0-9]+\\.[0-9][0-9] s of lab time\n"));
  EXPECT_THAT(out.str(), HasSubstr("summary: " + result.summary_path));
}

TEST(ImportWorkflowTest, ALabRunThatMissedItsGoalIsNotReadyAsASimulatedOneWouldBe) {
  // The lab's robots stayed where they started: the poses pass every check,
  // but no robot reached its goal.
  const formats::NpyArray start =
      formats::ReadNpyFile(testing::SimulatedExport() + "/upload/" + bridge::SubmissionFiles::kInitialPoses);
  const int64_t n = start.shape[1];
  const formats::NpyArray rows =
      bridge::testing::PerfectLabResult(testing::SimulatedExport(), [&](int64_t, double* row) {
        for (int64_t q = 0; q < 3 * n; ++q)
          row[bridge::ResultLayout::kFixedColumns + q] = start.values[static_cast<size_t>(q)];
      });
  std::ostringstream out;
  const ImportWorkflow::Result result = Import(rows, "missed_goal", out);
  EXPECT_EQ(result.imported.verdict(), world::RunVerdict::kClean);  // the lab part alone sees nothing wrong
  EXPECT_EQ(result.verdict(), world::RunVerdict::kNotReady);
  EXPECT_TRUE(result.report.judgement.Has("goal"));
  const nlohmann::json summary = ReadJson(result.summary_path);
  EXPECT_EQ(summary["verdict"], "not_ready");
  EXPECT_EQ(summary["goal"]["met"], false);
  EXPECT_EQ(summary["verdict_reasons"].back()["rule"], "goal");
  ImportWorkflow(out).PrintVerdict(result);
  EXPECT_THAT(out.str(), HasSubstr("verdict: not_ready (declared "));
  EXPECT_THAT(out.str(), ContainsRegex("robots, [0-9]+\\.[0-9][0-9] s; "));
  EXPECT_THAT(out.str(), HasSubstr("  - goal: "));
}

// Issue 33: an imported run's log ends, as every run's, on the one judge's
// verdict (DREAM_VERDICT), once: dream view of the log alone ends on it.
TEST(ImportWorkflowTest, TheImportedLogEndsOnceOnTheJudgedVerdict) {
  const formats::NpyArray start =
      formats::ReadNpyFile(testing::SimulatedExport() + "/upload/" + bridge::SubmissionFiles::kInitialPoses);
  const int64_t n = start.shape[1];
  const formats::NpyArray rows =  // the robots stayed where they started: not ready, the goal missed
      bridge::testing::PerfectLabResult(testing::SimulatedExport(), [&](int64_t, double* row) {
        for (int64_t q = 0; q < 3 * n; ++q)
          row[bridge::ResultLayout::kFixedColumns + q] = start.values[static_cast<size_t>(q)];
      });
  std::ostringstream out;
  const ImportWorkflow::Result result = Import(rows, "verdict_in_log", out);
  ASSERT_EQ(ImportWorkflow::ExitCodeOf(result), 5);
  const nlohmann::json summary = ReadJson(result.summary_path);
  const std::vector<lcm::LogRecord> events = lcm::LogReader::ReadAll(result.imported.log_path);
  ASSERT_EQ(static_cast<int64_t>(events.size()), summary["log_events"].get<int64_t>());
  ASSERT_EQ(events.back().channel, lcm::kVerdictChannel);
  for (size_t i = 0; i + 1 < events.size(); ++i) EXPECT_NE(events[i].channel, lcm::kVerdictChannel) << i;
  run_verdict_t verdict;
  ASSERT_TRUE(lcm::Decode(events.back().data.data(), static_cast<int>(events.back().data.size()), &verdict));
  EXPECT_EQ(verdict.verdict, run_verdict_t::NOT_READY);
  EXPECT_EQ(verdict.goal, run_verdict_t::GOAL_MISSED);
  EXPECT_EQ(verdict.exit_code, 5);
  EXPECT_EQ(verdict.step, summary["steps"].get<int64_t>());
  EXPECT_THAT(verdict.reasons, HasSubstr("goal: "));
  // The run's id: the poses', and summary.json's.
  robot_poses_t poses;
  ASSERT_EQ(events[2].channel, lcm::kPosesChannel);
  ASSERT_TRUE(lcm::Decode(events[2].data.data(), static_cast<int>(events[2].data.size()), &poses));
  EXPECT_EQ(verdict.run_id, poses.run_id);
  EXPECT_EQ(lcm::RunIdText(verdict.run_id), summary["run_id"].get<std::string>());

  // The log alone, without its summary.json: the view ends on the verdict it holds.
  const std::string alone = bridge::testing::NewFolder("workflow_import_verdict_alone") + "/run.lcmlog";
  fs::copy_file(result.imported.log_path, alone);
  ASSERT_TRUE(run_log::RunLog::Read(alone).verdict().has_value());
  const ViewReplay replay =
      ViewReplay::OfRun(alone, (fs::path(result.summary_path).parent_path() / "config.yaml").string(), "");
  ASSERT_TRUE(replay.setup.judged.has_value());
  EXPECT_EQ(replay.setup.judged->verdict, "not_ready");
}

TEST(ImportWorkflowTest, ALabRunsViolationsAreLocatedByTheWorldsRulesAsASimulatedRunsAre) {
  // Robot 0 stood past the right wall at rows 10..15 of the lab's result.
  const formats::NpyArray rows =
      bridge::testing::PerfectLabResult(testing::SimulatedExport(), [](int64_t k, double* row) {
        if (k >= 10 && k <= 15) row[bridge::ResultLayout::kFixedColumns] = 1.7;  // robot 0's x
      });
  std::ostringstream out;
  const ImportWorkflow::Result result = Import(rows, "outside", out);
  EXPECT_EQ(result.verdict(), world::RunVerdict::kRejected);
  const nlohmann::json located = ReadJson(result.summary_path)["violations_located"];
  ASSERT_EQ(located["listed"].size(), 1u) << located.dump();
  const nlohmann::json& entry = located["listed"][0];
  EXPECT_EQ(entry["kind"], "boundary");
  EXPECT_EQ(entry["robots"], nlohmann::json::array({0}));
  EXPECT_EQ(entry["last_step"].get<int64_t>() - entry["first_step"].get<int64_t>(), 5);
  EXPECT_DOUBLE_EQ(entry["position"][0].get<double>(), 1.7);
  EXPECT_EQ(located["unlisted"], 0);
}

TEST(ImportWorkflowTest, TheVerifiersRulesStayInTheVerdictBesideTheGoal) {
  const bridge::ExportedSubmission exported = bridge::ExportedSubmission::Read(testing::SimulatedExport());
  const std::optional<world::LabVerifierRules::Declaration> declared =
      ImportWorkflow::Declared(exported, exported.params.num_robots + 1, 0.0);
  ASSERT_TRUE(declared.has_value());
  EXPECT_EQ(declared->num_robots, exported.params.num_robots + 1);
  EXPECT_EQ(declared->duration_s, exported.UploadDeclaration().duration_s);  // not given: UPLOAD.txt's
  std::ostringstream out;
  const ImportWorkflow::Result result =
      Import(bridge::testing::PerfectLabResult(testing::SimulatedExport()), "declared", out, declared);
  EXPECT_EQ(result.verdict(), world::RunVerdict::kRejected);
  const nlohmann::json summary = ReadJson(result.summary_path);
  EXPECT_EQ(summary["verdict"], "rejected");
  EXPECT_EQ(summary["verdict_reasons"][0]["rule"], "verifier_robot_count");
  EXPECT_EQ(summary["lab"]["declared_from"], "options");
  EXPECT_EQ(summary["lab"]["declared_robots"], exported.params.num_robots + 1);
  EXPECT_FALSE(ImportWorkflow::Declared(exported, 0, 0.0).has_value());
}

TEST(ImportWorkflowTest, AFolderWithoutAResultIsRefusedByName) {
  const std::string dir = bridge::testing::NewFolder("workflow_import_empty");
  try {
    ImportWorkflow::ResultFile(dir);
    ADD_FAILURE() << "an empty folder passed for a result";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(dir + ": holds neither dream_result.npy nor dream_result.mat"));
  }
  EXPECT_EQ(ImportWorkflow::ResultFile(dir + "/x.npy"), dir + "/x.npy");
}

// A Robotarium script's lab run: dream export SCRIPT.py ships DREAM's recorder as the main file, which
// saves every pose the script read and every command it sent in the form every export's result has
// (settle rows of the start-up drive, experiment rows, a final pose). The export knows neither the robots
// nor the start: both come from the result, and the run is the one dream run SCRIPT.py makes for them.
formats::NpyArray ScriptResult(int settle_rows, int experiment_steps, bool final_row) {
  const int n = 2;
  formats::NpyArray rows;
  const int row_count = settle_rows + experiment_steps + (final_row ? 1 : 0);
  rows.shape = {row_count, bridge::ResultLayout::Columns(n)};
  rows.values.assign(static_cast<size_t>(rows.shape[0] * rows.shape[1]), 0.0);
  for (int r = 0; r < row_count; ++r) {
    const bool settle = r < settle_rows;
    const int step = settle ? r : r - settle_rows;
    double* row = &rows.values[static_cast<size_t>(r * rows.shape[1])];
    row[0] = settle ? 0.0 : (r < settle_rows + experiment_steps ? 1.0 : 2.0);
    row[1] = step;
    row[2] = 1000.0 + 0.033 * r;
    const double x = settle ? -0.6 : -0.5 + 0.1 * 0.033 * step;  // robot 0 drives at 0.1 m/s
    row[bridge::ResultLayout::X(n, 0)] = x;
    row[bridge::ResultLayout::X(n, 1)] = 0.5;
    row[bridge::ResultLayout::Y(n, 1)] = 0.3;
    row[bridge::ResultLayout::V(n, 0)] = row[0] == 2.0 ? 0.0 : 0.1;
  }
  return rows;
}

std::string ScriptExportFolder(const std::string& name) {
  const std::string dir = bridge::testing::NewFolder("workflow_import_script_" + name);
  bridge::testing::WriteText(dir + "/script_export.json",
                             R"({"script": "/home/me/go.py", "main_file": "dream_record.py", "sha256": "00"})");
  return dir;
}

TEST(ImportWorkflowTest, AScriptsLabRunIsImportedAsTheRunOfItsRobotsAndStart) {
  const std::string dir = ScriptExportFolder("complete");
  bridge::testing::WriteText(dir + "/dream_result.npy", formats::EncodeNpy(ScriptResult(4, 30, true)));
  // The recorder's record of the script's last check: robot 0 to (-0.4, 0) within 0.05 m.
  bridge::testing::WriteText(dir + "/dream_goal.json",
                             R"({"last_check": {"check": "at_position", "robots": [0], "targets": [[-0.4, 0.0]], )"
                             R"("position_error": 0.05, "rotation_error": null}, "checks": 30})");
  ImportWorkflow::Asked asked;
  asked.result = dir + "/dream_result.npy";
  asked.export_dir = dir;
  asked.out_dir = dir + "/out";
  asked.python_runtime_dir = dream::testing::SourceDir() + "/python";
  const ImportWorkflow::Options options = ImportWorkflow::OptionsOf(asked);
  std::ostringstream out;
  const ImportWorkflow::Result result = ImportWorkflow(out).Import(options);
  EXPECT_EQ(ImportWorkflow::ExitCodeOf(result), 0) << out.str();
  const nlohmann::json summary = ReadJson(result.summary_path);
  EXPECT_EQ(summary["robots"], 2);
  EXPECT_EQ(summary["steps"], 30);
  EXPECT_EQ(summary["lab"]["complete"], true);
  EXPECT_EQ(summary["lab"]["settle_steps"], 4);
  EXPECT_EQ(summary["lab"]["iterations"], 34);
  EXPECT_EQ(summary["lab"]["source_run"], "/home/me/go.py");
  // Judged by the script's own check, as its simulated run would be, on the lab's poses.
  EXPECT_EQ(summary["goal"]["has_criterion"], true);
  EXPECT_EQ(summary["goal"]["met"], true) << summary["goal"];
  EXPECT_THAT(summary["goal"]["detail"].get<std::string>(), HasSubstr("the script's last at_position check"));
  EXPECT_TRUE(fs::exists(dir + "/out/script_goal.json"));
  // The run config is a script run's, naming the script, its robots starting where the drive left them.
  const run_config::RunConfig config = run_config::LoadRunConfigFile(dir + "/out/config.yaml");
  EXPECT_EQ(config.script, "/home/me/go.py");
  ASSERT_EQ(config.initial_poses.size(), 2u);
  EXPECT_DOUBLE_EQ(config.initial_poses[0].x_m, -0.5);
  EXPECT_DOUBLE_EQ(config.initial_poses[1].y_m, 0.3);
  // The lab's poses are the log's: robot 0 ends 30 steps of 0.1 m/s on.
  const run_log::RunLog log = run_log::RunLog::Read(dir + "/out/run.lcmlog");
  EXPECT_NEAR(log.poses().back().x[0], -0.5 + 0.1 * 0.033 * 30, 1e-12);
  // Replayed without its script as the agent (dream lab-replay starts it; the workflow cannot): refused.
  LabReplayWorkflow::Options replay;
  replay.lab_dir = dir + "/out";
  try {
    LabReplayWorkflow(out).Replay(replay);
    ADD_FAILURE() << "a script's lab run was replayed";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("the lab run of a Robotarium script (/home/me/go.py)"));
  }
}

TEST(ImportWorkflowTest, AScriptsLabRunCutShortOrOfNoRobotCountIsSaidSo) {
  const std::string dir = ScriptExportFolder("short");
  const std::string python = dream::testing::SourceDir() + "/python";
  bridge::testing::WriteText(dir + "/cut.npy", formats::EncodeNpy(ScriptResult(2, 10, false)));
  std::ostringstream out;
  const ImportWorkflow::Result cut = ImportWorkflow(out).Import({dir + "/cut.npy", dir, dir + "/cut", {}, python});
  EXPECT_FALSE(cut.imported.lab.complete);
  EXPECT_EQ(ImportWorkflow::ExitCodeOf(cut), 4);  // cut short: the run did not finish
  formats::NpyArray odd = ScriptResult(2, 10, true);
  odd.shape[1] = 12;  // 3 + 9: no robot count
  odd.values.resize(static_cast<size_t>(odd.shape[0] * odd.shape[1]));
  bridge::testing::WriteText(dir + "/odd.npy", formats::EncodeNpy(odd));
  try {
    ImportWorkflow(out).Import({dir + "/odd.npy", dir, dir + "/odd", {}, python});
    ADD_FAILURE() << "a result of 12 columns was imported";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(dir + "/odd.npy: 12 columns are 3 + 5 N for no robot count"));
  }
  EXPECT_FALSE(fs::exists(dir + "/odd"));
}

}  // namespace
}  // namespace dream::workflows
