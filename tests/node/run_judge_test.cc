// JudgeRun and the summary: what went wrong on the bus (lost robots, failed
// controllers, command conflicts, bad messages) and the lab verifier's rules
// make the verdict, with one reason each, in summary.json.
#include "dream/node/run_judge.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dream/node/run_summary.h"
#include "dream/world/unicycle_world.h"

namespace dream::node {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

struct StillRun {
  run_config::RunConfig config;
  world::UnicycleWorld world;
  RunOutcome outcome;

  explicit StillRun(int steps) : world(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, {}) {
    config.name = "judged";
    config.num_robots = 3;
    for (int k = 0; k < steps; ++k) world.Step();
    outcome.steps = steps;
  }
};

const world::VerdictReason* Find(const world::RunJudgement& judgement, const std::string& rule) {
  for (const world::VerdictReason& reason : judgement.reasons()) {
    if (reason.rule == rule) return &reason;
  }
  return nullptr;
}

TEST(RunJudgeTest, AHealthyRunIsClean) {
  const StillRun run(30);
  const world::RunJudgement judgement = JudgeRun(run.config, run.outcome, run.world);
  EXPECT_EQ(judgement.verdict(), world::RunVerdict::kClean);
  EXPECT_TRUE(judgement.reasons().empty());
}

TEST(RunJudgeTest, EachThingThatWentWrongOnTheBusIsAReason) {
  StillRun run(30);
  run.outcome.robots_ever_lost = {1, 2};
  run.outcome.robot_faults = {{2, "step 7: ctl.py:3: in update: ValueError: x"}};
  run.outcome.command_conflicts = 4;
  run.outcome.bad_messages = {{"DREAM_CMD_0", 2}, {"DREAM_POSES", 1}};
  run.outcome.bad_message_first = {
      {"DREAM_CMD_0", "step 12: rejected command: answers step 13 but the world is at step 12"}};
  run.outcome.handler_failures = 1;
  run.outcome.dropped_messages = 12;
  const world::RunJudgement judgement = JudgeRun(run.config, run.outcome, run.world);
  EXPECT_EQ(judgement.verdict(), world::RunVerdict::kNotReady);
  ASSERT_NE(Find(judgement, "lost_robots"), nullptr);
  EXPECT_EQ(Find(judgement, "lost_robots")->problem.rfind("robot 1 lost", 0), 0u);  // 2 is under controller_failed
  ASSERT_NE(Find(judgement, "controller_failed"), nullptr);
  EXPECT_THAT(Find(judgement, "controller_failed")->problem,
              HasSubstr("robot 2 was lost, its controller failed at step 7"));
  ASSERT_NE(Find(judgement, "command_conflicts"), nullptr);
  EXPECT_THAT(Find(judgement, "command_conflicts")->problem, HasSubstr("4 commands"));
  ASSERT_NE(Find(judgement, "bad_messages"), nullptr);
  EXPECT_THAT(Find(judgement, "bad_messages")->problem, HasSubstr("3 undecodable or refused messages"));
  // What was refused, on which channel, how many, and from which step (it said only how many per channel).
  EXPECT_THAT(Find(judgement, "bad_messages")->problem,
              HasSubstr("DREAM_CMD_0: 2, the first at step 12: rejected command: answers step 13 but the world is at "
                        "step 12; DREAM_POSES: 1"));
  EXPECT_NE(Find(judgement, "handler_failures"), nullptr);
  ASSERT_NE(Find(judgement, "dropped_messages"), nullptr);
  EXPECT_THAT(Find(judgement, "dropped_messages")->problem, HasSubstr("12 messages were dropped"));
  EXPECT_EQ(Find(judgement, "did_not_finish"), nullptr);
  EXPECT_THAT(judgement.Text(), Not(HasSubstr("will run on the Robotarium")));
}

TEST(RunJudgeTest, ARunThatDidNotFinishIsNotReady) {
  StillRun run(3);
  run.outcome.end = RunOutcome::End::kStartTimeout;
  run.outcome.reason = "robot 1 never got an agent";
  const world::RunJudgement judgement = JudgeRun(run.config, run.outcome, run.world);
  EXPECT_EQ(judgement.verdict(), world::RunVerdict::kNotReady);
  ASSERT_NE(Find(judgement, "did_not_finish"), nullptr);
  EXPECT_THAT(Find(judgement, "did_not_finish")->problem, HasSubstr("robot 1 never got an agent"));
}

TEST(RunJudgeTest, TheLabCapCountsTheExportsSettleSteps) {
  // (27032 + 240 settle) x 0.033 s = 899.976 s fits; one step more does not.
  const StillRun fits(27032);
  EXPECT_EQ(JudgeRun(fits.config, fits.outcome, fits.world).verdict(), world::RunVerdict::kClean);
  const StillRun over(27033);
  const world::RunJudgement judgement = JudgeRun(over.config, over.outcome, over.world);
  EXPECT_EQ(judgement.verdict(), world::RunVerdict::kRejected);
  EXPECT_NE(Find(judgement, "lab_duration_cap"), nullptr);
}

TEST(RunJudgeTest, TheVerifierCountsRobotsOutsideWhenGiven) {
  const StillRun run(30);
  // The world saw none; a caller that re-counted on the log says 101.
  EXPECT_NE(Find(JudgeRun(run.config, run.outcome, run.world, 101), "verifier_out_of_bounds"), nullptr);
  EXPECT_EQ(Find(JudgeRun(run.config, run.outcome, run.world, 100), "verifier_out_of_bounds"), nullptr);
}

TEST(RunJudgeTest, SummaryHasTheVerdictAndItsReasons) {
  StillRun run(30);
  run.outcome.command_conflicts = 2;
  const nlohmann::json summary =
      RunSummary::Of(run.config, run.outcome, run.world, "run.lcmlog", JudgeRun(run.config, run.outcome, run.world))
          .Json();
  EXPECT_EQ(summary["verdict"], "not_ready");
  EXPECT_EQ(summary["robotarium_verdict"], "clean");
  ASSERT_EQ(summary["verdict_reasons"].size(), 1u);
  const nlohmann::json& reason = summary["verdict_reasons"][0];
  EXPECT_EQ(reason["rule"], "command_conflicts");
  EXPECT_EQ(reason["verdict"], "not_ready");
  EXPECT_THAT(reason["problem"].get<std::string>(), HasSubstr("2 commands"));
  EXPECT_THAT(reason["find_out"].get<std::string>(), HasSubstr("DREAM_APPLIED"));
  EXPECT_THAT(summary["robotarium_report"].get<std::string>(), HasSubstr("will run on the Robotarium"));
}

// A reason quoting a path with a byte that is not UTF-8 (a Latin-1 folder
// name) must not cost the run its summary: JsonText writes U+FFFD for it.
TEST(RunJudgeTest, SummaryOfAReasonThatIsNotUtf8IsStillWritten) {
  StillRun run(5);
  run.outcome.end = RunOutcome::End::kFailed;
  run.outcome.reason = "cannot write /tmp/r\xE9sultats/run.lcmlog";
  const nlohmann::ordered_json summary =
      RunSummary::Of(run.config, run.outcome, run.world, "run.lcmlog", JudgeRun(run.config, run.outcome, run.world))
          .Json();
  EXPECT_THROW((void)summary.dump(), nlohmann::json::type_error);  // what the writers did before
  const std::string text =
      RunSummary::Of(run.config, run.outcome, run.world, "run.lcmlog", JudgeRun(run.config, run.outcome, run.world))
          .Text();
  EXPECT_THAT(text, HasSubstr("/tmp/r\xEF\xBF\xBDsultats/run.lcmlog"));
  EXPECT_EQ(nlohmann::json::parse(text)["run"], "judged");
}

}  // namespace
}  // namespace dream::node
