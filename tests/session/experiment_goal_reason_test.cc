// ExperimentGoal as a verdict reason: a missed goal (metrics.goal, the kind's
// own rule) is the reason "goal" (not_ready); a kind without a rule never is.
// The rules themselves are tested with their kinds (tests/agents/goal_rules_test.cc).
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

nlohmann::json Judged(bool met, long long completion_step, const std::string& detail) {
  return {{"goal", {{"met", met}, {"completion_step", completion_step}, {"detail", detail}}}};
}

TEST(ExperimentGoalReason, AMissedGoalIsANotReadyReason) {
  const ExperimentGoal missed =
      ExperimentGoal::Judge(SummaryOf("go_to_goal", Judged(false, -1, "not all at their goals, worst 0.2 m")));
  const std::optional<world::VerdictReason> reason = missed.Reason();
  ASSERT_TRUE(reason.has_value());
  EXPECT_EQ(reason->rule, "goal");
  EXPECT_EQ(reason->verdict, world::RunVerdict::kNotReady);
  EXPECT_THAT(reason->problem, HasSubstr("the go_to_goal experiment missed its goal: not all at their goals"));
  EXPECT_EQ(missed.Json()["met"], false);
  EXPECT_EQ(missed.Json()["kind"], "go_to_goal");

  EXPECT_FALSE(ExperimentGoal::Judge(SummaryOf("go_to_goal", Judged(true, 40, "all at their goals"))).Reason());
  EXPECT_FALSE(ExperimentGoal::Judge(SummaryOf("my_kind", nlohmann::json::object())).Reason().has_value());
}

}  // namespace
}  // namespace dream::session
