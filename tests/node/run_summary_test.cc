// RunSummary: summary.json's one field list, written and read back through it;
// what a reader says of a summary.json whose fields are not what the list says.
#include "dream/node/run_summary.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dream/node/run_judge.h"
#include "dream/world/unicycle_world.h"

namespace dream::node {
namespace {

using ::testing::HasSubstr;

/// A two-robot run of 10 steps with a conflict and a fault: a summary with every kind of field filled.
RunSummary TenSteps() {
  run_config::RunConfig config;
  config.name = "typed";
  config.num_robots = 2;
  config.seed = 7;
  world::UnicycleWorld world(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, {});
  for (int k = 0; k < 10; ++k) world.Step();
  RunOutcome outcome;
  outcome.steps = 10;
  outcome.wall_time_s = 0.25;
  outcome.run_id = 0x1234;
  outcome.command_conflicts = 1;
  outcome.robots_ever_lost = {1};
  outcome.robot_faults = {{1, "step 3: ctl.py:1: in update: ValueError: x"}, {10, "step 4: y"}};
  outcome.bad_messages = {{"DREAM_CMD_1", 3}};
  return RunSummary::Of(config, outcome, world, "run.lcmlog", JudgeRun(config, outcome, world));
}

/// A file name of this process's own under the temporary folder (trees may test side by side).
std::filesystem::path TempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("dream_" + std::to_string(::getpid()) + "_" + name);
}

std::string Write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

/// The error RunSummary::FromJson throws for `json`, or "" when it reads.
std::string ReadError(const nlohmann::ordered_json& json) {
  try {
    RunSummary::FromJson(json, "runs/x/summary.json");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(RunSummaryTest, TheFieldsAreInSummaryJsonsOrder) {
  // The order docs/run-outputs.md describes, and readers of the text (python/, tests) see.
  RunSummary summary = TenSteps();
  summary.violations_located = nlohmann::ordered_json::object();
  summary.metrics = nlohmann::ordered_json::object();
  summary.goal = nlohmann::ordered_json::object();
  summary.sections["lab"] = nlohmann::ordered_json::object();
  std::vector<std::string> keys;
  const nlohmann::ordered_json json = summary.Json();
  for (auto it = json.begin(); it != json.end(); ++it) keys.push_back(it.key());
  const std::vector<std::string> expected = {"run",
                                             "config",
                                             "seed",
                                             "mode",
                                             "robots",
                                             "sim_only",
                                             "end",
                                             "reason",
                                             "steps",
                                             "max_steps",
                                             "simulated_time_s",
                                             "wall_time_s",
                                             "steps_per_second",
                                             "violations",
                                             "violations_located",
                                             "verdict",
                                             "verdict_reasons",
                                             "robotarium_verdict",
                                             "robotarium_report",
                                             "run_id",
                                             "rejected_commands",
                                             "command_conflicts",
                                             "other_worlds",
                                             "robots_ever_lost",
                                             "robot_faults",
                                             "robots_done",
                                             "bad_messages",
                                             "bad_message_senders",
                                             "refused_messages",
                                             "refused_log",
                                             "refused_log_events",
                                             "bad_message_first",
                                             "handler_failures",
                                             "dropped_messages",
                                             "log",
                                             "log_events",
                                             "final_poses",
                                             "metrics",
                                             "goal",
                                             "lab"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(json["verdict"], "not_ready");
  EXPECT_EQ(json["end"], "finished");
  EXPECT_EQ(json["run_id"], "0000000000001234");
  EXPECT_EQ(json["robot_faults"].begin().key(), "1");  // ids as text keys, in text order: "1", "10"
}

TEST(RunSummaryTest, ReadingBackGivesTheSameTextAndTypedFields) {
  RunSummary written = TenSteps();
  written.metrics = {{"min_pairwise_distance_m", 2.0}};
  written.sections["agents"] = {{"reports_missing", nlohmann::json::array()}};
  const std::filesystem::path path = TempPath("summary.json");
  const RunSummary read = RunSummary::Read(Write(path, written.Text()));
  std::filesystem::remove(path);
  EXPECT_EQ(read.Text(), written.Text());
  EXPECT_EQ(read.verdict, world::RunVerdict::kNotReady);
  EXPECT_EQ(read.robotarium_verdict, world::RunVerdict::kClean);
  ASSERT_FALSE(read.verdict_reasons.empty());
  EXPECT_EQ(read.verdict_reasons[0].verdict, world::RunVerdict::kNotReady);
  EXPECT_EQ(read.end, RunOutcome::End::kFinished);
  EXPECT_EQ(read.seed, 7u);
  EXPECT_EQ(read.steps, 10);
  EXPECT_TRUE(read.Has("agents"));
  EXPECT_TRUE(read.Has("metrics"));
  EXPECT_FALSE(read.Has("realism"));
}

TEST(RunSummaryTest, AMissingFieldKeepsItsDefaultAndIsNotHad) {
  const RunSummary read = RunSummary::FromJson({{"run", "old"}, {"verdict", "warning"}}, "summary.json");
  EXPECT_EQ(read.run, "old");
  EXPECT_EQ(read.verdict, world::RunVerdict::kWarning);
  EXPECT_TRUE(read.Has("verdict"));
  EXPECT_FALSE(read.Has("verdict_reasons"));
  EXPECT_TRUE(read.run_id.empty());
}

TEST(RunSummaryTest, ABadFieldIsAnErrorNamingTheFileTheFieldAndTheValue) {
  EXPECT_EQ(ReadError({{"verdict", "great"}}),
            "runs/x/summary.json: verdict: expected one of clean, warning, not_ready, rejected, got \"great\"");
  EXPECT_EQ(ReadError({{"end", 3}}),
            "runs/x/summary.json: end: expected one of finished, interrupted, start_timeout, failed, got 3");
  EXPECT_EQ(ReadError({{"steps", -1}}), "runs/x/summary.json: steps: expected a whole number >= 0, got -1");
  EXPECT_EQ(ReadError({{"steps", 1.5}}), "runs/x/summary.json: steps: expected a whole number >= 0, got 1.5");
  EXPECT_EQ(ReadError({{"seed", "7"}}), "runs/x/summary.json: seed: expected a whole number >= 0, got \"7\"");
  EXPECT_EQ(ReadError({{"run_id", 12}}), "runs/x/summary.json: run_id: expected text, got 12");
  EXPECT_EQ(ReadError({{"sim_only", "yes"}}), "runs/x/summary.json: sim_only: expected true or false, got \"yes\"");
  EXPECT_EQ(ReadError({{"violations", {{"collision_errors", -2}}}}),
            "runs/x/summary.json: violations.collision_errors: expected a whole number >= 0, got -2");
  EXPECT_EQ(ReadError({{"metrics", {1, 2}}}), "runs/x/summary.json: metrics: expected an object, got [1,2]");
  EXPECT_EQ(ReadError({{"verdict_reasons", {{{"rule", "goal"}, {"verdict", "fine"}}}}}),
            "runs/x/summary.json: verdict_reasons[0].verdict: expected one of clean, warning, not_ready, "
            "rejected, got \"fine\"");
  EXPECT_EQ(ReadError({{"verdict_reasons", {{{"rule", "goal"}, {"verdict", "warning"}, {"problem", "p"}}}}}),
            "runs/x/summary.json: verdict_reasons[0].find_out: expected text, got nothing");
  EXPECT_EQ(ReadError(nlohmann::ordered_json::array()),
            "runs/x/summary.json: not a run's summary: a JSON array, not an object");
  // A huge value is named by its start, not copied whole into the message.
  const std::string error = ReadError({{"reason", std::vector<int>(100000, 1)}});
  EXPECT_THAT(error, HasSubstr("reason: expected text, got [1,1,1"));
  EXPECT_LT(error.size(), 200u);
}

TEST(RunSummaryTest, AFileThatIsNotJsonOrTooLargeIsAnErrorNamingIt) {
  const std::string bad = Write(TempPath("bad_summary.json"), "{\"verdict\": ");
  try {
    RunSummary::Read(bad);
    ADD_FAILURE() << "read a cut summary.json";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(bad + ": not valid JSON"));
  }
  std::filesystem::resize_file(bad, RunSummary::kMaxBytes + 1);
  try {
    RunSummary::Read(bad);
    ADD_FAILURE() << "read a summary.json over its bound";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(bad));
  }
  std::filesystem::remove(bad);
  EXPECT_THROW(RunSummary::Read(TempPath("no_such_summary.json").string()), std::runtime_error);
}

}  // namespace
}  // namespace dream::node
