// ExportWorkflow: where an export goes, and a refusal as a result.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "../bridge/bridge_test_support.h"
#include "dream/workflows/export_workflow.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(ExportWorkflowTest, ARunIsExportedAndWhatToUploadPrinted) {
  std::ostringstream out;
  ExportWorkflow::Options options;
  options.run_dir = testing::SimulatedRun();
  options.out_dir = bridge::testing::NewFolder("export_workflow") + "/export";
  const ExportWorkflow::Result result = ExportWorkflow(out).Export(options);
  ASSERT_FALSE(result.refused) << result.refusal;
  EXPECT_TRUE(fs::exists(options.out_dir + "/UPLOAD.txt"));
  EXPECT_EQ(result.summary.out_dir, options.out_dir);
  EXPECT_THAT(out.str(), HasSubstr("written: " + options.out_dir + "/UPLOAD.txt"));
  EXPECT_THAT(out.str(), HasSubstr("Number of robots to declare"));
}

TEST(ExportWorkflowTest, WithoutOutAnExportGoesToExportsAndTheConfigsName) {
  ExportWorkflow::Options options;
  options.run_dir = testing::SimulatedRun();
  EXPECT_EQ(ExportWorkflow::OutDir(options), "exports/go_to_goal");
  options.out_dir = "elsewhere";
  EXPECT_EQ(ExportWorkflow::OutDir(options), "elsewhere");
}

// Exports go by the config's name: exporting a second run of one config replaced the first's
// export without a word.
TEST(ExportWorkflowTest, AnExportOfAnotherRunInTheSameFolderSaysWhatItReplaced) {
  const std::string dir = bridge::testing::NewFolder("export_workflow_replaced");
  const std::string other_run = dir + "/go_to_goal_2";
  fs::copy(testing::SimulatedRun(), other_run, fs::copy_options::recursive);
  ExportWorkflow::Options options;
  options.out_dir = dir + "/export";
  options.run_dir = testing::SimulatedRun();
  std::ostringstream first;
  ASSERT_FALSE(ExportWorkflow(first).Export(options).refused);
  std::ostringstream again;
  ASSERT_FALSE(ExportWorkflow(again).Export(options).refused);
  EXPECT_THAT(again.str(), ::testing::Not(HasSubstr("replaced: ")));  // the same run's export, made again
  options.run_dir = other_run;
  std::ostringstream other;
  ASSERT_FALSE(ExportWorkflow(other).Export(options).refused);
  EXPECT_THAT(other.str(), HasSubstr("replaced: " + options.out_dir + " held the export of " +
                                     fs::weakly_canonical(testing::SimulatedRun()).string() +
                                     " (--out DIR keeps each run's export)"));
}

// `dream export sweeps/ring` said "sweeps/ring/config.yaml: cannot open the config file".
TEST(ExportWorkflowTest, AFolderThatIsNoRunIsNamedWithWhatToPassInstead) {
  const std::string dir = bridge::testing::NewFolder("export_workflow_no_run");
  const auto error_of = [](const std::string& run_dir) {
    ExportWorkflow::Asked asked;
    asked.run_dir = run_dir;
    std::string refusal;
    try {
      ExportWorkflow().ExportAsAsked(asked, &refusal);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return "no error, refusal '" + refusal + "'";
  };
  EXPECT_EQ(error_of(dir + "/runs/rng"), dir +
                                             "/runs/rng: no such run folder (pass the folder dream run wrote, "
                                             "runs/<name>, or a script SCRIPT.py)");
  fs::create_directories(dir + "/sweep");
  bridge::testing::WriteText(dir + "/sweep/sweep.json", "{}");
  EXPECT_EQ(error_of(dir + "/sweep"), dir + "/sweep: a sweep's folder; export one of its runs, " + dir +
                                          "/sweep/runs/<run> (its sweep.md lists them)");
  EXPECT_EQ(error_of(dir),
            dir + ": not a run folder (it has no config.yaml; pass the folder dream run wrote, runs/<name>)");
}

TEST(ExportWorkflowTest, ARunTheLabWouldRefuseIsARefusalAndNothingIsWritten) {
  // The simulated run, with a summary.json that says its goal was missed.
  const std::string run = bridge::testing::NewFolder("export_workflow_not_ready");
  for (const char* file : {"config.yaml", "run.lcmlog"}) {
    fs::copy_file(testing::SimulatedRun() + "/" + file, run + "/" + file);
  }
  bridge::testing::WriteText(run + "/summary.json", R"({"max_steps": 1500, "verdict": "not_ready", "verdict_reasons": [
    {"rule": "goal", "verdict": "not_ready", "problem": "missed its goal", "find_out": "summary.json goal"}]})");
  std::ostringstream out;
  ExportWorkflow::Options options;
  options.run_dir = run;
  options.out_dir = bridge::testing::NewFolder("export_workflow_refused") + "/export";
  const ExportWorkflow::Result result = ExportWorkflow(out).Export(options);
  EXPECT_TRUE(result.refused);
  EXPECT_THAT(result.refusal, HasSubstr("goal: missed its goal"));
  EXPECT_FALSE(fs::exists(options.out_dir));
  EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace dream::workflows
