// dream export: pre-validation as the lab would judge a run (each refusal
// names its rule, robot, step and fix), the files written, nothing written on
// refusal, and no way to get code from a config into the submission script.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>

#include "bridge_test_support.h"
#include "dream/bridge/lab_import.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/pre_validation.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/bridge/submission_format.h"
#include "dream/bridge/submission_params.h"
#include "dream/config/config_error.h"
#include "dream/run_status_t.hpp"
#include "../support/source_tree.h"

namespace dream::bridge {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// n robots on a grid 0.5 m apart, standing still for `steps` steps.
RunTrack StillTrack(int n, int64_t steps) {
  RunTrack track;
  track.num_robots = n;
  for (int64_t k = 0; k <= steps; ++k) {
    track.utime.push_back(k * 33000);
    for (int i = 0; i < n; ++i) {
      track.poses.push_back(world::Pose2{-1.4 + 0.5 * (i % 6), -0.75 + 0.5 * (i / 6), 0.0});
      track.commands.push_back(world::UnicycleCommand{});
    }
    track.obstacles.emplace_back();
  }
  return track;
}

RunEnd Finished() {
  RunEnd end;
  end.seen = true;
  end.state = run_status_t::FINISHED;
  end.detail = "reached the step limit";
  return end;
}

std::vector<std::string> Rules(const std::vector<ExportProblem>& problems) {
  std::vector<std::string> rules;
  for (const ExportProblem& p : problems) rules.push_back(p.rule);
  return rules;
}

// One table knows each strategy: its name, how it parses, and its words in upload.txt.
TEST(ExportOptionsTest, EveryStrategyParsesFromItsNameAndIsDescribed) {
  EXPECT_THAT(StrategyNames(), ElementsAre("track", "replay", "controller"));
  for (const std::string& name : StrategyNames()) {
    const Strategy strategy = ParseStrategy(name);
    EXPECT_EQ(StrategyName(strategy), name);
    EXPECT_STRNE(StrategyDescription(strategy), "?");
  }
  EXPECT_STREQ(StrategyDescription(Strategy::kReplay), "recorded commands, open loop");
  try {
    ParseStrategy("closed");
    ADD_FAILURE() << "an unknown strategy parsed";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown strategy 'closed'; allowed: track, replay, controller"));
  }
}

TEST(PreValidationTest, CleanRunPasses) {
  EXPECT_TRUE(PreValidate(StillTrack(20, 100), Finished(), world::WorldParams{}, 240).empty());
}

TEST(PreValidationTest, MoreThanTwentyRobotsIsRefused) {
  const auto problems = PreValidate(StillTrack(21, 10), Finished(), world::WorldParams{}, 240);
  ASSERT_THAT(Rules(problems), ElementsAre("robots"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("the run has 21 robots; the Robotarium runs 1 to 20"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("Fix: set `robots:` to at most 20"));
}

TEST(PreValidationTest, DurationOverTheCapIsRefusedAndTheLimitIsNamed) {
  // 27,000 steps + 240 settle steps = 898.9 s fit; 27,100 + 240 = 902.2 s do not.
  EXPECT_TRUE(PreValidate(StillTrack(2, 27000), Finished(), world::WorldParams{}, 240).empty());
  const auto problems = PreValidate(StillTrack(2, 27100), Finished(), world::WorldParams{}, 240);
  ASSERT_THAT(Rules(problems), ElementsAre("duration"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("902.2 s on the lab, over its cap of 900 s"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("run at most 27032 steps"));
}

TEST(PreValidationTest, UnfinishedRunIsRefused) {
  RunEnd end = Finished();
  end.state = run_status_t::ABORTED;
  end.detail = "interrupted (Ctrl-C or SIGTERM)";
  const auto problems = PreValidate(StillTrack(2, 10), end, world::WorldParams{}, 240);
  ASSERT_THAT(Rules(problems), ElementsAre("finished"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("interrupted (Ctrl-C or SIGTERM)"));
}

TEST(PreValidationTest, BoundaryCollisionAndObstacleErrorsNameRobotAndFirstStep) {
  RunTrack track = StillTrack(4, 20);
  for (int64_t k = 7; k <= 9; ++k) track.poses[static_cast<size_t>(k * 4 + 0)].x_m = -1.65;  // robot 0 out
  for (int64_t k = 5; k <= 20; ++k) {                                                        // robot 2 onto robot 1
    track.poses[static_cast<size_t>(k * 4 + 2)] = world::Pose2{track.pose(k, 1).x_m + 0.1, track.pose(k, 1).y_m, 0.0};
  }
  for (int64_t k = 12; k <= 20; ++k) track.obstacles[static_cast<size_t>(k)] = {{3, 0.1, -0.75, 0.1, 0.1, 0, 0}};
  const auto problems = PreValidate(track, Finished(), world::WorldParams{}, 240);
  ASSERT_THAT(Rules(problems), ElementsAre("boundary", "collision", "obstacle"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("boundary: robot 0, step 7: is outside the arena at (-1.650, -0.750)"));
  EXPECT_THAT(problems[1].Text(), HasSubstr("collision: robots 1 and 2, step 5: are closer than 0.135 m"));
  EXPECT_THAT(problems[2].Text(), HasSubstr("obstacle: robot 3 and obstacle 3, step 12: touches the virtual obstacle"));
  for (const ExportProblem& p : problems) EXPECT_THAT(p.Text(), HasSubstr("Fix: ")) << p.Text();
}

TEST(PreValidationTest, StartPosesMustBeReachableByTheLabsStartUp) {
  RunTrack track = StillTrack(3, 5);
  for (int64_t k = 0; k <= 5; ++k) {
    track.poses[static_cast<size_t>(k * 3 + 1)] = world::Pose2{track.pose(k, 0).x_m + 0.18, track.pose(k, 0).y_m, 0.0};
    track.poses[static_cast<size_t>(k * 3 + 2)] = world::Pose2{1.57, 0.0, 0.0};
  }
  const auto problems = PreValidate(track, Finished(), world::WorldParams{}, 240);
  ASSERT_THAT(Rules(problems), ElementsAre("start_inside_arena", "start_spacing"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("robot 2, step 0: starts at (1.570, 0.000), closer than 0.055 m"));
  EXPECT_THAT(problems[1].Text(), HasSubstr("robots 0 and 1, step 0: start poses are 0.180 m apart"));
}

TEST(PreValidationTest, CrowdedStartIsAWarningNotARefusal) {
  EXPECT_TRUE(StartUpWarnings(StillTrack(12, 5)).empty());  // 0.5 m apart
  RunTrack packed = StillTrack(9, 5);
  for (int64_t k = 0; k <= 5; ++k) {
    for (int i = 0; i < 9; ++i) {
      packed.poses[static_cast<size_t>(k * 9 + i)] = world::Pose2{0.5 + 0.3 * (i % 3), -0.6 + 0.3 * (i / 3), 0.0};
    }
  }
  EXPECT_TRUE(PreValidate(packed, Finished(), world::WorldParams{}, 240).empty());
  const std::vector<std::string> warnings = StartUpWarnings(packed);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("start poses are crowded (robot 4 has 4 others within 0.38 m)"));
}

class ExportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_dir_ = new std::string(testing::MakeRunFolder("export_run", testing::ShippedConfig("go_to_goal")));
  }
  static void TearDownTestSuite() { delete run_dir_; }
  static std::string* run_dir_;
};
std::string* ExportTest::run_dir_ = nullptr;

TEST_F(ExportTest, WritesTheSubmissionAndInstructions) {
  const std::string out = testing::NewFolder("export_out");
  const ExportSummary summary = ExportSubmission(*run_dir_, out, ExportOptions{});
  EXPECT_THAT(testing::FilesIn(out),
              ElementsAre("UPLOAD.txt", "config.yaml", "export.json", "upload", "upload/dream_initial_poses.npy",
                          "upload/dream_main.py", "upload/dream_params.npy", "upload/dream_reference_commands.npy",
                          "upload/dream_reference_poses.npy"));
  EXPECT_EQ(summary.num_robots, 8);
  EXPECT_GT(summary.steps, 150);
  const std::string text = testing::ReadText(out + "/UPLOAD.txt");
  EXPECT_THAT(text, HasSubstr("dream_main.py    <- mark this file as MAIN"));
  EXPECT_THAT(text, HasSubstr("Number of robots to declare: 8"));
  EXPECT_THAT(text, HasSubstr("Estimated duration to declare: "));
  EXPECT_THAT(text, HasSubstr("Strategy: track (recorded commands plus feedback on the pose error)"));
  const SubmissionParams params =
      SubmissionParams::FromNpy(formats::ReadNpyFile(out + "/upload/dream_params.npy"), "p");
  EXPECT_EQ(params.num_robots, 8);
  EXPECT_EQ(params.steps, summary.steps);
  EXPECT_EQ(params.options.strategy, Strategy::kTrack);
  EXPECT_EQ(formats::ReadNpyFile(out + "/upload/dream_reference_poses.npy").shape,
            (std::vector<int64_t>{summary.steps + 1, 3, 8}));
  EXPECT_EQ(formats::ReadNpyFile(out + "/upload/dream_reference_commands.npy").shape,
            (std::vector<int64_t>{summary.steps, 2, 8}));
  // The reference is the recorded run, exactly.
  const RunTrack track = ReadRunTrack(*run_dir_ + "/run.lcmlog");
  const formats::NpyArray poses = formats::ReadNpyFile(out + "/upload/dream_reference_poses.npy");
  EXPECT_EQ(poses.values[static_cast<size_t>(100 * 24 + 8 + 3)], track.pose(100, 3).y_m);
}

// Issue 23: an upload whose dream_initial_poses.npy was edited by +0.3 m passed
// check-submission clean, its 20 cm tracking error put down to the start-up drive.
TEST_F(ExportTest, AnUploadFileEditedAfterTheExportIsNamed) {
  const std::string out = testing::NewFolder("export_digests");
  ExportSubmission(*run_dir_, out, ExportOptions{});
  EXPECT_TRUE(ExportedSubmission::Read(out).digests_checked);
  auto read_error = [&] {
    try {
      ExportedSubmission::Read(out);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("read without an error");
  };
  const std::string poses = out + "/upload/dream_initial_poses.npy";
  const std::string original = testing::ReadText(poses);
  formats::NpyArray moved = formats::ReadNpyFile(poses);
  moved.values[0] += 0.3;
  testing::WriteText(poses, formats::EncodeNpy(moved));
  EXPECT_THAT(read_error(), HasSubstr(poses + ": changed after the export (its SHA-256 is "));
  EXPECT_THAT(read_error(), HasSubstr("export the run again"));
  testing::WriteText(poses, original);
  EXPECT_TRUE(ExportedSubmission::Read(out).digests_checked);
  testing::WriteText(out + "/upload/extra.py", "print('hi')\n");
  EXPECT_THAT(read_error(), HasSubstr(out + "/upload/extra.py: not a file of this export"));
  fs::remove(out + "/upload/extra.py");
  fs::remove(poses);
  EXPECT_THAT(read_error(), HasSubstr(poses + ": missing"));
}

TEST_F(ExportTest, RefusedRunWritesNothing) {
  // The same run judged against a 5-robot lab.
  std::string config = testing::ShippedConfig("go_to_goal");
  const std::string out = testing::NewFolder("export_refused") + "/out";
  RunEnd end;
  const RunTrack track = ReadRunTrack(*run_dir_ + "/run.lcmlog", &end);
  LabLimits small_lab;
  small_lab.max_robots = 5;
  EXPECT_THAT(Rules(PreValidate(track, end, world::WorldParams{}, 240, small_lab)), ElementsAre("robots"));
  // A run that collides: robots 0 and 1 drive to the same goal.
  config.replace(config.find("- [0.172, 0.323]"), 16, "- [0.416, 0.134]");
  const std::string bad_run = testing::MakeRunFolder("export_colliding", config);
  try {
    ExportSubmission(bad_run, out, ExportOptions{});
    ADD_FAILURE() << "exported a colliding run";
  } catch (const ExportRefused& refused) {
    // It names the log whose steps it counts (a damaged log reads as a refused run).
    EXPECT_THAT(refused.what(), ::testing::StartsWith(bad_run + "/run.lcmlog: the Robotarium would refuse this run"));
    EXPECT_THAT(Rules(refused.problems()), ::testing::Contains("collision"));
  }
  EXPECT_FALSE(fs::exists(out)) << "a refused export must not write anything";
}

TEST_F(ExportTest, MissingOrForeignInputsNameTheFile) {
  const std::string out = testing::NewFolder("export_bad_inputs");
  const std::string empty = testing::NewFolder("export_empty_run");
  EXPECT_THROW(
      {
        try {
          ExportSubmission(empty, out + "/a", ExportOptions{});
        } catch (const std::runtime_error& e) {
          EXPECT_THAT(e.what(), HasSubstr(empty + "/config.yaml: missing"));
          throw;
        }
      },
      std::runtime_error);
  const std::string foreign = testing::NewFolder("export_foreign_run");
  testing::WriteText(foreign + "/config.yaml", testing::ShippedConfig("go_to_goal"));
  testing::WriteText(foreign + "/run.lcmlog", "this is not a log\n");
  EXPECT_THROW(ExportSubmission(foreign, out + "/b", ExportOptions{}), std::runtime_error);
  EXPECT_FALSE(fs::exists(out + "/a"));
  EXPECT_FALSE(fs::exists(out + "/b"));
}

TEST_F(ExportTest, OutputThatWouldEscapeItsFolderIsRefused) {
  const std::string base = testing::NewFolder("export_escape");
  const std::string outside = testing::NewFolder("export_escape_target");
  fs::create_directories(base + "/out");
  fs::create_directory_symlink(outside, base + "/out/upload");  // upload/ leads elsewhere
  EXPECT_THROW(
      {
        try {
          ExportSubmission(*run_dir_, base + "/out", ExportOptions{});
        } catch (const std::runtime_error& e) {
          EXPECT_THAT(e.what(), HasSubstr("outside the output folder"));
          throw;
        }
      },
      std::runtime_error);
  EXPECT_TRUE(testing::FilesIn(outside).empty());
}

// Nothing from a config reaches the script: the script is a fixed template
// and every datum is a float64 .npy. A config whose free-text field is built
// to break out of any string literal changes no byte of the script.
TEST_F(ExportTest, ConfigStringsCannotInjectCodeIntoTheSubmission) {
  const std::string payload =
      "x'''\\\"\\\"\\\"\\n__import__('os').system('touch /tmp/dream_pwned') # ${HOME} %s {0} \\x00";
  std::string config = testing::ShippedConfig("go_to_goal");
  const size_t line = config.find("description:");
  config.replace(line, config.find('\n', line) - line, "description: \"" + payload + "\"");
  ASSERT_THAT(testing::LoadConfigText(config).source, HasSubstr("test.yaml"));
  const std::string hostile_run = testing::MakeRunFolder("export_hostile", config);
  const std::string out = testing::NewFolder("export_hostile_out");
  ExportSubmission(hostile_run, out, ExportOptions{});

  const std::string script = testing::ReadText(out + "/upload/dream_main.py");
  EXPECT_EQ(script, SubmissionScriptTemplate()) << "the script must be the fixed template, byte for byte";
  EXPECT_EQ(script, testing::ReadText(dream::testing::SourceDir() + "/bridge/python/dream_main.py"));
  for (const char* fragment : {"dream_pwned", "__import__('os')", "${HOME}", "go_to_goal", "eight robots"}) {
    EXPECT_EQ(script.find(fragment), std::string::npos) << fragment;
  }
  // Every data file is plain float64 numbers (np.load(..., allow_pickle=False) can read nothing else).
  for (const std::string& name : testing::FilesIn(out + "/upload")) {
    if (name == SubmissionFiles::kMainScript) continue;
    const std::string bytes = testing::ReadText(out + "/upload/" + name);
    EXPECT_NO_THROW(formats::DecodeNpy(bytes, name)) << name;
    EXPECT_EQ(bytes.find("pwned"), std::string::npos) << name;
  }
  // The run name cannot carry code either: the config refuses it.
  std::string bad_name = testing::ShippedConfig("go_to_goal");
  bad_name.replace(bad_name.find("name: go_to_goal"), 16, "name: \"a'; import os #\"");
  EXPECT_THROW(testing::LoadConfigText(bad_name), config::ConfigError);
}

TEST(SubmissionTemplateTest, ParameterIndicesMatchTheScript) {
  const std::string& script = SubmissionScriptTemplate();
  const std::vector<std::pair<const char*, int>> indices = {
      {"P_MAGIC", kParamMagic},
      {"P_FORMAT_VERSION", kParamFormatVersion},
      {"P_NUM_ROBOTS", kParamNumRobots},
      {"P_STEPS", kParamSteps},
      {"P_STRATEGY", kParamStrategy},
      {"P_BARRIERS", kParamBarriers},
      {"P_SETTLE_MAX_STEPS", kParamSettleMaxSteps},
      {"P_SETTLE_POSITION_TOLERANCE", kParamSettlePositionTolerance},
      {"P_SETTLE_HEADING_TOLERANCE", kParamSettleHeadingTolerance},
      {"P_SETTLE_GAIN_V", kParamSettleGainV},
      {"P_SETTLE_GAIN_W", kParamSettleGainW},
      {"P_GAIN_X", kParamGainX},
      {"P_GAIN_Y", kParamGainY},
      {"P_GAIN_THETA", kParamGainTheta},
      {"P_SAVE_EVERY_STEPS", kParamSaveEverySteps},
      {"P_WHEEL_RADIUS", kParamWheelRadius},
      {"P_BASE_LENGTH", kParamBaseLength},
      {"P_MAX_WHEEL_SPEED", kParamMaxWheelSpeed},
      {"P_STOP_WHEN_DONE", kParamStopWhenDone},
      {"P_MAX_ABS_V", kParamMaxAbsV},
      {"P_MAX_ABS_W", kParamMaxAbsW},
      {"P_BARRIER_SAFETY_RADIUS", kParamBarrierSafetyRadius},
      {"P_BARRIER_GAIN", kParamBarrierGain},
      {"P_BARRIER_PROJECTION_DISTANCE", kParamBarrierProjectionDistance},
      {"P_BARRIER_MAGNITUDE_LIMIT", kParamBarrierMagnitudeLimit},
      {"P_BARRIER_HAS_BOUNDARY", kParamBarrierHasBoundary},
      {"P_BARRIER_BOUNDARY", kParamBarrierBoundaryXMin},
      {"P_COUNT", kParamCount},
      {"O_ID", kObstacleId},
      {"O_CENTER", kObstacleCenterX},
      {"O_SIZE", kObstacleWidth},
      {"O_VELOCITY", kObstacleVelocityX},
      {"O_COUNT", kObstacleColumns},
  };
  for (const auto& [name, index] : indices) {
    EXPECT_NE(script.find(std::string("\n") + name + " = " + std::to_string(index) + "\n"), std::string::npos) << name;
  }
  EXPECT_NE(script.find("\nMAGIC = 1146242369.0"), std::string::npos);
  EXPECT_NE(script.find("\nFORMAT_VERSION = " + std::to_string(static_cast<int>(kFormatVersion)) + ".0\n"),
            std::string::npos);
  EXPECT_NE(script.find("\nSTRATEGY_CONTROLLER = 2.0\n"), std::string::npos);
  EXPECT_NE(script.find(std::string("\nCONTROLLER_SPEC_FILE = \"") + SubmissionFiles::kControllerSpec + "\"\n"),
            std::string::npos);
  EXPECT_NE(script.find(std::string("\nOBSTACLES_FILE = \"") + SubmissionFiles::kObstacles + "\"\n"),
            std::string::npos);
  EXPECT_NE(script.find("\nFIXED_COLUMNS = " + std::to_string(ResultLayout::kFixedColumns) + "\n"), std::string::npos);
  EXPECT_NE(script.find("allow_pickle=False"), std::string::npos);
  EXPECT_EQ(script.find("allow_pickle=True"), std::string::npos);
  EXPECT_EQ(script.find("eval("), std::string::npos);
  EXPECT_EQ(script.find("exec("), std::string::npos);
}

// --- the lab verifier's rules (world::LabVerifierRules) in pre-validation ---

/// Moves robot `robot` of a StillTrack below the arena (y < -1) for steps [from, from + count).
void PutOutside(RunTrack* track, int robot, int64_t from, int64_t count) {
  for (int64_t k = from; k < from + count; ++k) {
    track->poses[static_cast<size_t>(k * track->num_robots + robot)].y_m = -1.05;
  }
}

TEST(VerifierRulesTest, OutsideHundredRobotStepsIsDebugsErrorAndHundredAndOneTheVerifiers) {
  // Two robots outside: 50 + 50 = 100 robot-steps (50 steps with any outside).
  RunTrack track = StillTrack(3, 300);
  PutOutside(&track, 0, 10, 50);
  PutOutside(&track, 1, 10, 50);
  EXPECT_EQ(VerifierCounts(track, world::WorldParams{}).robots_outside_boundaries, 100);
  EXPECT_THAT(Rules(PreValidate(track, Finished(), world::WorldParams{}, 240)), ElementsAre("boundary", "boundary"));
  PutOutside(&track, 1, 60, 1);  // 101
  EXPECT_EQ(VerifierCounts(track, world::WorldParams{}).robots_outside_boundaries, 101);
  const auto problems = PreValidate(track, Finished(), world::WorldParams{}, 240);
  EXPECT_THAT(Rules(problems), ElementsAre("verifier_out_of_bounds", "boundary", "boundary"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("101 times (robots x steps)"));
}

TEST(VerifierRulesTest, TooCloseHundredPairStepsAndHundredAndOne) {
  RunTrack track = StillTrack(3, 300);
  auto close_for = [&track](int64_t steps) {
    for (int64_t k = 0; k <= 300; ++k) {
      const world::Pose2 beside{track.pose(k, 0).x_m + 0.1, track.pose(k, 0).y_m, 0.0};
      track.poses[static_cast<size_t>(k * 3 + 1)] = k >= 20 && k < 20 + steps ? beside : StillTrack(3, 0).pose(0, 1);
    }
  };
  close_for(100);
  EXPECT_EQ(VerifierCounts(track, world::WorldParams{}).robots_too_close, 100);
  EXPECT_THAT(Rules(PreValidate(track, Finished(), world::WorldParams{}, 240)), ElementsAre("collision"));
  close_for(101);
  EXPECT_THAT(Rules(PreValidate(track, Finished(), world::WorldParams{}, 240)),
              ElementsAre("verifier_too_close", "collision"));
}

TEST(VerifierRulesTest, CountsAreThoseOfTheStepsTheWorldValidated) {
  // The last recorded pose is never validated by a step: not counted.
  RunTrack track = StillTrack(2, 10);
  PutOutside(&track, 0, 10, 1);
  EXPECT_EQ(VerifierCounts(track, world::WorldParams{}).robots_outside_boundaries, 0);
  EXPECT_EQ(VerifierCounts(track, world::WorldParams{}).iterations, 10);
}

TEST(VerifierRulesTest, TheDeclaredRobotCountAndDuration) {
  const RunTrack track = StillTrack(4, 100);
  // The default declaration is what UPLOAD.txt gives: it always passes.
  EXPECT_TRUE(PreValidate(track, Finished(), world::WorldParams{}, 240).empty());
  // (100 + 240) x 0.033 = 11.22 s: 1.5 x 7.49 s = 11.235 s passes, 1.5 x 7.47 s = 11.205 s does not.
  EXPECT_TRUE(
      PreValidate(track, Finished(), world::WorldParams{}, 240, {}, -1, world::LabVerifierRules::Declaration{4, 7.49})
          .empty());
  EXPECT_THAT(Rules(PreValidate(track, Finished(), world::WorldParams{}, 240, {}, -1,
                                world::LabVerifierRules::Declaration{4, 7.47})),
              ElementsAre("verifier_duration"));
  const auto problems =
      PreValidate(track, Finished(), world::WorldParams{}, 240, {}, -1, world::LabVerifierRules::Declaration{5, 11.22});
  ASSERT_THAT(Rules(problems), ElementsAre("verifier_robot_count"));
  EXPECT_THAT(problems[0].Text(), HasSubstr("asks for 4 robots but 5 are declared"));
  // A declaration over the lab's 900 s cap, although the run is short.
  EXPECT_THAT(Rules(PreValidate(track, Finished(), world::WorldParams{}, 240, {}, -1,
                                world::LabVerifierRules::Declaration{4, 901.0})),
              ElementsAre("lab_duration_cap"));
}

TEST_F(ExportTest, SummaryReasonsRefuseTheRunUnlessForced) {
  // The shipped run, with a summary.json that calls it not ready.
  const std::string run = testing::NewFolder("export_not_ready");
  for (const char* file : {"config.yaml", "run.lcmlog"}) fs::copy_file(*run_dir_ + "/" + file, run + "/" + file);
  testing::WriteText(run + "/summary.json", R"({"max_steps": 1500, "verdict": "not_ready", "verdict_reasons": [
    {"rule": "goal", "verdict": "not_ready", "problem": "missed its goal", "find_out": "summary.json metrics"},
    {"rule": "command_conflicts", "verdict": "not_ready", "problem": "4 commands", "find_out": "DREAM_APPLIED"},
    {"rule": "actuator", "verdict": "warning", "problem": "3 steps", "find_out": ""},
    {"rule": "controller_failed", "verdict": "not_ready", "problem": "found again in the log", "find_out": ""}]})");
  const std::string out = testing::NewFolder("export_not_ready_out") + "/out";
  try {
    ExportSubmission(run, out, ExportOptions{});
    ADD_FAILURE() << "exported a run summary.json calls not ready";
  } catch (const ExportRefused& refused) {
    EXPECT_THAT(Rules(refused.problems()), ElementsAre("goal", "command_conflicts"));
    EXPECT_THAT(refused.what(),
                HasSubstr("goal: missed its goal. Fix: summary.json metrics; or export anyway with --force"));
  }
  EXPECT_FALSE(fs::exists(out));
  ExportOptions forced;
  forced.force = true;
  const ExportSummary summary = ExportSubmission(run, out, forced);
  ASSERT_EQ(summary.warnings.size(), 2u);
  EXPECT_THAT(summary.warnings[0], HasSubstr("goal: missed its goal"));
  EXPECT_THAT(summary.warnings[0], HasSubstr("(exported anyway: --force)"));
  EXPECT_THAT(testing::ReadText(out + "/UPLOAD.txt"), HasSubstr("WARNING: command_conflicts: 4 commands"));

  testing::WriteText(run + "/summary.json", R"({"verdict_reasons": "not a list"})");
  try {
    ExportSubmission(run, testing::NewFolder("export_bad_summary") + "/out", forced);
    ADD_FAILURE() << "a malformed summary.json was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("summary.json: verdict_reasons: expected a list, got \"not a list\""));
  }
}

}  // namespace
}  // namespace dream::bridge
