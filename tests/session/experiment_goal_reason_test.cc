// ExperimentGoal as a verdict reason: a missed goal (metrics.goal, the kind's
// own rule) is the reason "goal" (not_ready); a kind without a rule never is.
// The rules themselves are tested with their kinds (tests/agent_host/goal_rules_test.cc).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dream/session/experiment_goal.h"

namespace dream::session {
namespace {

using ::testing::HasSubstr;

nlohmann::json SummaryOf(const std::string& kind, nlohmann::json metrics) {
  metrics["kind"] = kind;
  return {{"robots", 3}, {"steps", 900}, {"robots_done", nlohmann::json::array()}, {"metrics", metrics}};
}

/// `summary` read as summary.json's readers read it.
node::RunSummary Typed(const nlohmann::json& summary) {
  return node::RunSummary::FromJson(nlohmann::ordered_json(summary), "summary.json");
}

nlohmann::json Judged(bool met, long long completion_step, const std::string& detail) {
  return {{"goal", {{"met", met}, {"completion_step", completion_step}, {"detail", detail}}}};
}

TEST(ExperimentGoalReason, AMissedGoalIsANotReadyReason) {
  const ExperimentGoal missed =
      ExperimentGoal::Judge(Typed(SummaryOf("go_to_goal", Judged(false, -1, "not all at their goals, worst 0.2 m"))));
  const std::optional<world::VerdictReason> reason = missed.Reason();
  ASSERT_TRUE(reason.has_value());
  EXPECT_EQ(reason->rule, "goal");
  EXPECT_EQ(reason->verdict, world::RunVerdict::kNotReady);
  EXPECT_THAT(reason->problem, HasSubstr("the go_to_goal experiment missed its goal: not all at their goals"));
  EXPECT_EQ(missed.Json()["met"], false);
  EXPECT_EQ(missed.Json()["kind"], "go_to_goal");

  EXPECT_FALSE(ExperimentGoal::Judge(Typed(SummaryOf("go_to_goal", Judged(true, 40, "all at their goals")))).Reason());
  EXPECT_FALSE(ExperimentGoal::Judge(Typed(SummaryOf("my_kind", nlohmann::json::object()))).Reason().has_value());
}

// Metrics that could not be computed (a goal() that raised or hung, unusable
// goal points) are a goal that could not be judged: not ready, and said so
// apart from a goal the run missed (issue 34: RunReporter never excuses it as
// cut short by --steps).
TEST(ExperimentGoalReason, AGoalThatCouldNotBeJudgedIsNotReadyAndSaysWhy) {
  nlohmann::json summary = SummaryOf("python", nlohmann::json::object());
  summary["metrics"] = {{"error", "pair.py:70: in goal: ValueError: broken rule"}};
  const ExperimentGoal failed = ExperimentGoal::Judge(Typed(summary));
  EXPECT_TRUE(failed.has_criterion);
  EXPECT_FALSE(failed.met);
  EXPECT_EQ(failed.judge_error, "pair.py:70: in goal: ValueError: broken rule");
  const std::optional<world::VerdictReason> reason = failed.Reason();
  ASSERT_TRUE(reason.has_value());
  EXPECT_EQ(reason->verdict, world::RunVerdict::kNotReady);
  EXPECT_THAT(reason->problem, HasSubstr("goal could not be judged: pair.py:70: in goal: ValueError: broken rule"));
  EXPECT_EQ(failed.Json()["judge_error"], "pair.py:70: in goal: ValueError: broken rule");

  const ExperimentGoal judged = ExperimentGoal::Judge(Typed(SummaryOf("go_to_goal", Judged(false, -1, "worst 0.2 m"))));
  EXPECT_TRUE(judged.judge_error.empty());
  EXPECT_FALSE(judged.Json().contains("judge_error"));
}

}  // namespace
}  // namespace dream::session
