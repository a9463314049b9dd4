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
#include "dream/formats/npy_file.h"
#include "dream/bridge/submission_format.h"
#include "dream/files/file_text.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/robot_poses_t.hpp"
#include "dream/run_log/run_log.h"
#include "dream/run_verdict_t.hpp"
#include "dream/workflows/import_workflow.h"
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

// dream export SCRIPT.py uploads the script as it is: it saves no dream_result.npy, so its export
// folder is refused by what it is, not as "not written by dream export".
TEST(ImportWorkflowTest, AScriptsExportIsRefusedSayingWhy) {
  const std::string dir = bridge::testing::NewFolder("workflow_import_script_export");
  std::ofstream(dir + "/script_export.json") << "{}";
  ImportWorkflow::Asked asked;
  asked.result = dir + "/dream_result.npy";
  asked.export_dir = dir;
  try {
    ImportWorkflow::OptionsOf(asked);
    ADD_FAILURE() << "a script's export was taken for a run's";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(dir + ": the export of a Robotarium script (script_export.json)"));
    EXPECT_THAT(e.what(), HasSubstr("cannot read its lab run yet"));
  }
}

}  // namespace
}  // namespace dream::workflows
