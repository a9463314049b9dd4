// LabReplayWorkflow and CalibrationExportWorkflow, run in this process (no
// `dream` process): a lab run replayed against its controllers with the
// agents hosted by the session, and the calibration drive run and exported.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "../bridge/bridge_test_support.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/submission_format.h"
#include "dream/files/file_text.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/run_verdict_t.hpp"
#include "dream/workflows/calibration_export_workflow.h"
#include "dream/workflows/import_workflow.h"
#include "dream/workflows/lab_replay_workflow.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

nlohmann::json ReadJson(const std::string& path) { return nlohmann::json::parse(files::ReadFileText(path)); }

/// A perfect lab result of the simulated run's export, imported as dream import does.
std::string ImportedLabRun(const std::string& name) {
  const std::string dir = bridge::testing::NewFolder("workflow_lab_replay_" + name);
  bridge::testing::WriteText(dir + "/" + bridge::SubmissionFiles::kResult,
                             formats::EncodeNpy(bridge::testing::PerfectLabResult(testing::SimulatedExport())));
  std::ostringstream quiet;
  ImportWorkflow(quiet).Import({dir, testing::SimulatedExport(), dir + "/lab", std::nullopt, ""});
  return dir;
}

TEST(LabReplayWorkflowTest, ReplaysTheLabsPosesAgainstTheControllersHostedByTheSession) {
  const std::string dir = ImportedLabRun("whole");
  std::ostringstream report;
  LabReplayWorkflow::Options options;
  options.lab_dir = dir + "/lab";
  options.out_dir = dir + "/replay";
  options.steps = 40;
  const LabReplayWorkflow::Result result = LabReplayWorkflow(report).Replay(options);
  // The agents answered every step: the world compared their commands with the lab's.
  ASSERT_TRUE(result.agreement.has_value());
  const nlohmann::json summary = ReadJson(dir + "/replay/summary.json");
  EXPECT_EQ(summary["steps"], 40);
  EXPECT_EQ(summary["end"], "finished");
  EXPECT_EQ(summary["lab_replay"]["lab_run"], fs::absolute(options.lab_dir).string());
  EXPECT_EQ(summary["lab_replay"]["lab_command_channels"], "DREAM_LAB_CMD_<id>");
  const nlohmann::json agreement = nlohmann::json::parse(result.agreement->Json().dump());
  EXPECT_EQ(summary["lab_replay"]["agents_vs_lab_commands"], agreement);
  EXPECT_NE(result.exit_code, session::kExitRunFailed);
  EXPECT_NE(result.exit_code, session::kExitInterrupted);
  EXPECT_THAT(report.str(), HasSubstr(dir + "/replay"));
  // Its log, replayed from a log that ends on the lab run's verdict, ends on its own, once (issue 33).
  const std::vector<lcm::LogRecord> events = lcm::LogReader::ReadAll(dir + "/replay/run.lcmlog");
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(std::count_if(events.begin(), events.end(),
                          [](const lcm::LogRecord& event) { return event.channel == lcm::kVerdictChannel; }),
            1);
  ASSERT_EQ(events.back().channel, lcm::kVerdictChannel);
  run_verdict_t verdict;
  ASSERT_TRUE(lcm::Decode(events.back().data.data(), static_cast<int>(events.back().data.size()), &verdict));
  EXPECT_EQ(verdict.exit_code, result.exit_code);
  EXPECT_EQ(lcm::RunIdText(verdict.run_id), summary["run_id"].get<std::string>());
  ASSERT_TRUE(verdict.verdict >= run_verdict_t::CLEAN && verdict.verdict <= run_verdict_t::REJECTED);
  static const char* kNames[] = {"clean", "warning", "not_ready", "rejected"};
  EXPECT_EQ(kNames[verdict.verdict], summary["verdict"].get<std::string>());
}

TEST(LabReplayWorkflowTest, AFolderWithoutALabRunIsRefusedByNameAndNothingIsWritten) {
  const std::string dir = bridge::testing::NewFolder("workflow_lab_replay_missing");
  LabReplayWorkflow::Options options;
  options.lab_dir = dir;
  options.out_dir = dir + "/replay";
  std::ostringstream report;
  try {
    LabReplayWorkflow(report).Replay(options);
    FAIL() << "a folder without config.yaml and run.lcmlog was replayed";
  } catch (const std::exception& error) {
    EXPECT_THAT(error.what(), HasSubstr(dir));
  }
  EXPECT_FALSE(fs::exists(options.out_dir));
}

TEST(CalibrationExportWorkflowTest, RefusesARobotCountOutsideTheLabsLimitsBeforeAnythingRuns) {
  const std::string dir = bridge::testing::NewFolder("workflow_calibration_refused");
  CalibrationExportWorkflow::Options options;
  options.out_dir = dir + "/export";
  options.run_dir = dir + "/run";
  for (int robots : {0, 21}) {
    options.robots = robots;
    try {
      CalibrationExportWorkflow().Export(options);
      FAIL() << robots << " robots were run";
    } catch (const std::runtime_error& error) {
      EXPECT_THAT(error.what(), HasSubstr("--robots " + std::to_string(robots)));
    }
  }
  EXPECT_FALSE(fs::exists(options.out_dir));
  EXPECT_FALSE(fs::exists(options.run_dir));
}

TEST(CalibrationExportWorkflowTest, RunsTheDriveWithItsAgentsHereAndExportsItOpenLoop) {
  const std::string dir = bridge::testing::NewFolder("workflow_calibration_export");
  CalibrationExportWorkflow::Options options;
  options.robots = 1;
  options.out_dir = dir + "/export";
  options.run_dir = dir + "/run";
  std::ostringstream out;
  std::ostringstream err;
  const CalibrationExportWorkflow::Result result = CalibrationExportWorkflow(out, err).Export(options);
  EXPECT_EQ(result.exit_code, session::kExitOk) << err.str();
  EXPECT_EQ(result.run_dir, options.run_dir);
  EXPECT_EQ(ReadJson(options.run_dir + "/summary.json")["verdict"], "clean");
  ASSERT_TRUE(result.exported.has_value());
  EXPECT_EQ(result.exported->num_robots, 1);
  EXPECT_TRUE(fs::exists(options.out_dir + "/UPLOAD.txt"));
  EXPECT_THAT(out.str(), HasSubstr("the simulated run: " + options.run_dir));
  // A second export into the same run folder is refused: it holds a run now.
  options.out_dir = dir + "/export_2";
  EXPECT_THROW(CalibrationExportWorkflow(out, err).Export(options), std::runtime_error);
}

}  // namespace
}  // namespace dream::workflows
