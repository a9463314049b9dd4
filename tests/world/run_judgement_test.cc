// RunJudgement: the verdict is the worst reason's; the printed text is
// debug()'s own, word for word, until a reason beyond it says otherwise, and
// then never says "will run on the Robotarium".
#include "dream/world/run_judgement.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace dream::world {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const VerdictReason kLost{"lost_robots", RunVerdict::kNotReady, "robot 2 lost", "summary.json robots_ever_lost"};

TEST(RunJudgementTest, CleanRunPrintsDebugTextExactly) {
  const RunReport report = RunReport::FromViolations(30, ViolationCounts{});
  const RunJudgement judgement(report);
  EXPECT_EQ(judgement.verdict(), RunVerdict::kClean);
  EXPECT_TRUE(judgement.reasons().empty());
  EXPECT_EQ(judgement.Text(), report.Text());
}

TEST(RunJudgementTest, OfficialCountsBecomeReasons) {
  ViolationCounts counts;
  counts.actuator_errors = 3;
  const RunJudgement warning(RunReport::FromViolations(30, counts));
  EXPECT_EQ(warning.verdict(), RunVerdict::kWarning);
  EXPECT_TRUE(warning.Has("actuator"));
  EXPECT_EQ(warning.Text(), RunReport::FromViolations(30, counts).Text());  // still debug()'s own case

  counts.collision_errors = 4;
  counts.boundary_errors = 1;
  const RunJudgement rejected(RunReport::FromViolations(30, counts));
  EXPECT_EQ(rejected.verdict(), RunVerdict::kRejected);
  EXPECT_TRUE(rejected.Has("collision") && rejected.Has("boundary") && rejected.Has("actuator"));
  EXPECT_FALSE(rejected.Has("obstacle"));
}

TEST(RunJudgementTest, ANotReadyReasonReplacesWillRun) {
  RunJudgement judgement(RunReport::FromViolations(30, ViolationCounts{}));
  judgement.Add(kLost);
  EXPECT_EQ(judgement.verdict(), RunVerdict::kNotReady);
  const std::string text = judgement.Text();
  EXPECT_THAT(text, Not(HasSubstr("will run on the Robotarium")));
  EXPECT_THAT(text, HasSubstr("Your simulation took approximately 0.99 real seconds to execute.\n\n"));
  EXPECT_THAT(text, HasSubstr("NOT ready for the Robotarium"));
  EXPECT_THAT(text, HasSubstr("  - lost_robots: robot 2 lost (more: summary.json robots_ever_lost)\n"));
}

TEST(RunJudgementTest, WarningPlusNotReadyListsBoth) {
  ViolationCounts counts;
  counts.actuator_errors = 3;
  RunJudgement judgement(RunReport::FromViolations(30, counts));
  judgement.Add(kLost);
  EXPECT_EQ(judgement.verdict(), RunVerdict::kNotReady);
  EXPECT_THAT(judgement.Text(), Not(HasSubstr("will run on the Robotarium")));
  EXPECT_THAT(judgement.Text(), HasSubstr("  - actuator: "));
  EXPECT_THAT(judgement.Text(), HasSubstr("  - lost_robots: "));
}

TEST(RunJudgementTest, AWarningBeyondDebugSaysTheRunRunsWithWarnings) {
  RunJudgement judgement(RunReport::FromViolations(30, ViolationCounts{}));
  judgement.Add({"tracker_lost", RunVerdict::kWarning, "robot 1 (from step 200) lost to the tracker",
                 "summary.json realism_stats"});
  EXPECT_EQ(judgement.verdict(), RunVerdict::kWarning);
  const std::string text = judgement.Text();
  EXPECT_THAT(text, Not(HasSubstr("NOT ready")));
  EXPECT_THAT(text, Not(HasSubstr("No errors or warnings")));
  EXPECT_THAT(text, HasSubstr("your script will run on the Robotarium, with warnings:\n"));
  EXPECT_THAT(text, HasSubstr("  - tracker_lost: robot 1 (from step 200) lost to the tracker"));
}

TEST(RunJudgementTest, RejectedKeepsDebugTextAndAddsTheRest) {
  ViolationCounts counts;
  counts.collision_errors = 2;
  const RunReport report = RunReport::FromViolations(30, counts);
  RunJudgement judgement(report);
  judgement.Add(kLost);
  EXPECT_EQ(judgement.verdict(), RunVerdict::kRejected);  // the worse of rejected and not ready
  EXPECT_EQ(judgement.Text(), report.Text() + "\nAlso:\n  - " + kLost.Text() + "\n");
}

TEST(RunJudgementTest, AVerifierRuleRejectsACleanLookingRun) {
  RunJudgement judgement(RunReport::FromViolations(30, ViolationCounts{}));
  judgement.Add({"lab_duration_cap", RunVerdict::kRejected, "too long", ""});
  EXPECT_EQ(judgement.verdict(), RunVerdict::kRejected);
  EXPECT_THAT(judgement.Text(), HasSubstr("will NOT run on the Robotarium"));
  EXPECT_THAT(judgement.Text(), Not(HasSubstr("will run on the Robotarium")));
  EXPECT_THAT(judgement.Text(), HasSubstr("  - lab_duration_cap: too long\n"));
}

TEST(RunJudgementTest, VerdictNames) {
  EXPECT_STREQ(RunVerdictName(RunVerdict::kNotReady), "not_ready");
  EXPECT_LT(RunVerdict::kWarning, RunVerdict::kNotReady);
  EXPECT_LT(RunVerdict::kNotReady, RunVerdict::kRejected);
}

TEST(RunJudgementTest, EveryVerdictNameParsesBackAndNothingElseDoes) {
  for (RunVerdict verdict : {RunVerdict::kClean, RunVerdict::kWarning, RunVerdict::kNotReady, RunVerdict::kRejected}) {
    EXPECT_EQ(ParseRunVerdict(RunVerdictName(verdict)), verdict) << RunVerdictName(verdict);
  }
  EXPECT_EQ(ParseRunVerdict("unknown"), std::nullopt);
  EXPECT_EQ(ParseRunVerdict("Clean"), std::nullopt);
  EXPECT_EQ(ParseRunVerdict(""), std::nullopt);
}

}  // namespace
}  // namespace dream::world
