// CheckSubmission with a fake runner: what it makes of each way the runner
// can end, and what it writes, with no process started.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../bridge/bridge_test_support.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/submission_format.h"
#include "dream/files/file_text.h"
#include "dream/workflows/check_submission.h"
#include "dream/workflows/script_export.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using Outcome = CheckSubmission::Outcome;

/// What the fake runner does: the report it writes (none when null) and
/// whether it leaves the lab's result behind.
struct FakeRunner {
  nlohmann::json report;
  bool writes_result = true;
  CheckSubmission::ScriptRun ends;
  std::vector<std::string> argv;                  ///< what it was started with
  std::function<void(int64_t, double*)> perturb;  ///< changes the lab's rows (PerfectLabResult's)
};

class CheckSubmissionTest : public ::testing::Test {
 protected:
  CheckSubmission::Options Options() const {
    CheckSubmission::Options options;
    options.export_dir = testing::SimulatedExport();
    options.out_dir = out_dir_;
    options.python = "python-of-the-test";
    options.runner_script = "run_submission.py";
    options.standin = true;
    return options;
  }

  CheckSubmission::Tools Tools() {
    CheckSubmission::Tools tools;
    tools.run_script = [this](const std::vector<std::string>& argv) {
      runner_.argv = argv;
      const auto at = [&argv](const std::string& option) { return *(std::find(argv.begin(), argv.end(), option) + 1); };
      if (runner_.writes_result) {
        bridge::testing::WriteText(
            at("--workdir") + "/" + bridge::SubmissionFiles::kResult,
            formats::EncodeNpy(bridge::testing::PerfectLabResult(testing::SimulatedExport(), runner_.perturb)));
      }
      if (!runner_.report.is_null()) bridge::testing::WriteText(at("--report"), runner_.report.dump());
      return runner_.ends;
    };
    tools.replay_lab = [](const std::string&, const std::string&) -> CheckSubmission::Replay {
      throw std::runtime_error("a track export is never replayed");
    };
    tools.choose_folder = [this](const std::string& out, const std::string& default_out, bool) {
      ++folders_chosen_;
      default_out_ = default_out;
      fs::create_directories(out);
      return out;
    };
    return tools;
  }

  CheckSubmission::Result Check(const CheckSubmission::Options& options) {
    return CheckSubmission(options, Tools(), out_).Run();
  }

  static nlohmann::json Passed() {
    return {{"ok", true},
            {"simulator", "standin"},
            {"verdict", "clean"},
            {"debug_text", "No errors\n"},
            {"warnings", nlohmann::json::array()}};
  }

  std::string out_dir_ = bridge::testing::NewFolder("check_submission") + "/check";
  FakeRunner runner_;
  int folders_chosen_ = 0;
  std::string default_out_;  ///< the folder chosen when --out is not given
  std::ostringstream out_;
};

TEST_F(CheckSubmissionTest, ARunnerThatPassesGivesAnImportedRunComparedWithTheSimulatedOne) {
  runner_.report = Passed();
  const CheckSubmission::Result result = Check(Options());
  EXPECT_EQ(result.outcome, Outcome::kPassed) << result.error;
  EXPECT_THAT(runner_.argv,
              ::testing::ElementsAre("python-of-the-test", "run_submission.py", "--upload",
                                     testing::SimulatedExport() + "/upload", "--workdir", out_dir_ + "/lab_files",
                                     "--report", out_dir_ + "/check_report.json", "--standin"));
  const nlohmann::json check = nlohmann::json::parse(files::ReadFileText(out_dir_ + "/check.json"));
  EXPECT_EQ(check["verdict"], "clean");
  EXPECT_EQ(check["complete"], true);
  EXPECT_EQ(check["compared_with"], testing::SimulatedRun());
  EXPECT_EQ(check["tracking_max_m"], 0.0);                   // a perfect lab drives the recorded poses
  EXPECT_FALSE(check.contains("controllers_on_lab_poses"));  // a track export
  // The imported run is reported as every run is.
  const nlohmann::json summary = nlohmann::json::parse(files::ReadFileText(out_dir_ + "/summary.json"));
  EXPECT_EQ(summary["verdict"], "clean");
  EXPECT_EQ(summary["goal"]["met"], true);
  EXPECT_TRUE(fs::exists(out_dir_ + "/comparison.json"));
  EXPECT_THAT(out_.str(), HasSubstr("simulator: DREAM's stand-in (--standin)"));
}

TEST_F(CheckSubmissionTest, AStandInUsedForWantOfTheOfficialSaysHowToNameTheOfficial) {
  runner_.report = Passed();
  CheckSubmission::Options options = Options();
  options.standin = false;
  EXPECT_EQ(Check(options).outcome, Outcome::kPassed);
  EXPECT_THAT(out_.str(), HasSubstr("simulator: DREAM's stand-in (the official one was not found: --simulator DIR or "
                                    "$ROBOTARIUM_PYTHON_SIMULATOR)"));
}

TEST_F(CheckSubmissionTest, EachWayTheRunnerFailsHasItsOutcome) {
  runner_.writes_result = false;
  runner_.ends = {5, false};
  EXPECT_EQ(Check(Options()).outcome, Outcome::kNoOfficialSimulator);
  runner_.ends = {1, false};
  const CheckSubmission::Result no_report = Check(Options());
  EXPECT_EQ(no_report.outcome, Outcome::kRunnerFailed);
  EXPECT_THAT(no_report.error, HasSubstr("exit 1"));
  runner_.ends = {0, true};
  EXPECT_EQ(Check(Options()).outcome, Outcome::kInterrupted);
  runner_.ends = {0, false};
  runner_.report = {{"ok", false}, {"error", "NameError: x"}};
  const CheckSubmission::Result raised = Check(Options());
  EXPECT_EQ(raised.outcome, Outcome::kScriptFailed);
  EXPECT_THAT(raised.error, HasSubstr("NameError: x"));
  runner_.report = {{"ok", false}, {"startup_timeout", true}, {"error", "slow"}};
  EXPECT_EQ(Check(Options()).outcome, Outcome::kStartupTimedOut);
  EXPECT_FALSE(fs::exists(out_dir_ + "/check.json"));
}

TEST_F(CheckSubmissionTest, DebugsVerdictIsReadAsAVerdict) {
  runner_.report = Passed();
  runner_.report["verdict"] = "rejected";
  EXPECT_EQ(Check(Options()).outcome, Outcome::kRejected);
  runner_.report["verdict"] = "warning";
  EXPECT_EQ(Check(Options()).outcome, Outcome::kPassed);
  EXPECT_THAT(out_.str(), HasSubstr("WARNING: the script ran, but with debug() warnings"));
}

// Issue 33, one judge: debug() saw nothing wrong, but the lab run misses its
// goal: check-submission says not ready, as dream import of the same result
// does, in its outcome (exit 5), check.json and what it prints.
TEST_F(CheckSubmissionTest, ALabRunThatMissesItsGoalIsNotReadyAsDreamImportSays) {
  runner_.report = Passed();
  const int64_t steps =
      formats::ReadNpyFile(testing::SimulatedExport() + "/upload/" + bridge::SubmissionFiles::kReferenceCommands)
          .shape[0];
  constexpr int robots = 8;  // the shipped go_to_goal
  // Every robot drifts 6 cm to the right over the run: no collision, no jump,
  // but none ends within go_to_goal's 2 cm of its goal.
  runner_.perturb = [steps](int64_t k, double* row) {
    for (int robot = 0; robot < robots; ++robot) {
      row[bridge::ResultLayout::X(robots, robot)] += 0.06 * static_cast<double>(k) / static_cast<double>(steps);
    }
  };
  const CheckSubmission::Result result = Check(Options());
  EXPECT_EQ(result.outcome, Outcome::kNotReady) << out_.str();
  const nlohmann::json check = nlohmann::json::parse(files::ReadFileText(out_dir_ + "/check.json"));
  EXPECT_EQ(check["verdict"], "not_ready");
  EXPECT_EQ(check["debug_verdict"], "clean");
  EXPECT_EQ(check["goal"]["met"], false);
  ASSERT_FALSE(check["verdict_reasons"].empty());
  EXPECT_EQ(check["verdict_reasons"][0]["rule"], "goal");
  const nlohmann::json summary = nlohmann::json::parse(files::ReadFileText(out_dir_ + "/summary.json"));
  EXPECT_EQ(summary["verdict"], check["verdict"]);
  EXPECT_THAT(out_.str(), HasSubstr("goal: missed"));
  EXPECT_THAT(out_.str(), HasSubstr("verdict: not_ready"));

  runner_.perturb = nullptr;
  const CheckSubmission::Result passed = Check(Options());
  EXPECT_EQ(passed.outcome, Outcome::kPassed);
  EXPECT_THAT(out_.str(), HasSubstr("goal: met at step"));
}

// A script's export was checked into runs/dream_record_check/, named after the
// recorder every script's upload has: the script names it, as it names its run.
TEST_F(CheckSubmissionTest, AScriptsCheckIsNamedAfterTheScriptNotTheRecorder) {
  const std::string dir = bridge::testing::NewFolder("check_script_submission");
  bridge::testing::WriteText(dir + "/my_script.py", "import numpy as np\n");
  fs::create_directories(dir + "/runtime/rps_dream");
  bridge::testing::WriteText(dir + "/runtime/rps_dream/dream_record.py", "SCRIPT = \"__DREAM_SCRIPT__\"\n");
  ScriptExport::Options exporting;
  exporting.script_path = dir + "/my_script.py";
  exporting.out_dir = dir + "/export";
  exporting.python_runtime_dir = dir + "/runtime";
  ScriptExport().Export(exporting, [](const std::vector<std::string>&) {
    return ScriptExport::Checked{0, "{\"imports\": [\"numpy\"], \"not_on_robotarium\": []}"};
  });
  runner_.report = Passed();
  runner_.writes_result = false;
  CheckSubmission::Options options = Options();
  options.export_dir = exporting.out_dir;
  EXPECT_EQ(Check(options).outcome, Outcome::kPassed) << out_.str();
  EXPECT_EQ(default_out_, "runs/my_script_check");
}

TEST_F(CheckSubmissionTest, AWrongSimulatorFolderIsNamedBeforeAnyFolderIsMade) {
  CheckSubmission::Options options = Options();
  options.standin = false;
  options.simulator_from_environment = bridge::testing::NewFolder("not_a_simulator");
  try {
    Check(options);
    ADD_FAILURE() << "a folder without rps/robotarium.py passed for a simulator";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("$ROBOTARIUM_PYTHON_SIMULATOR " + options.simulator_from_environment +
                                    ": has no rps/robotarium.py"));
  }
  options.out_dir = testing::SimulatedRun();
  options.simulator_from_environment.clear();
  EXPECT_THROW(Check(options), std::runtime_error);  // --out is the run it compares with
  EXPECT_EQ(folders_chosen_, 0);
}

}  // namespace
}  // namespace dream::workflows
