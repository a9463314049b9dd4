// ExperimentGoal as a verdict reason: a missed goal is the reason "goal"
// (not_ready); a kind without a criterion never is. voronoi_coverage with
// blocks moving to the end never settles, and is judged by its cost then.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "experiment_goal.h"

namespace dream::cli {
namespace {

using ::testing::HasSubstr;

nlohmann::json SummaryOf(const std::string& kind, nlohmann::json metrics) {
  metrics["kind"] = kind;
  return {{"robots", 3}, {"steps", 900}, {"robots_done", nlohmann::json::array()}, {"metrics", metrics}};
}

TEST(ExperimentGoalReason, AMissedGoalIsANotReadyReason) {
  const ExperimentGoal missed =
      ExperimentGoal::Judge(SummaryOf("go_to_goal", {{"all_arrived_step", -1}, {"final_max_goal_error_m", 0.2}}));
  const std::optional<sim::VerdictReason> reason = missed.Reason();
  ASSERT_TRUE(reason.has_value());
  EXPECT_EQ(reason->rule, "goal");
  EXPECT_EQ(reason->verdict, sim::RunVerdict::kNotReady);
  EXPECT_THAT(reason->problem, HasSubstr("the go_to_goal experiment missed its goal: not all at their goals"));
  EXPECT_EQ(missed.Json()["met"], false);
  EXPECT_EQ(missed.Json()["kind"], "go_to_goal");

  EXPECT_FALSE(ExperimentGoal::Judge(SummaryOf("go_to_goal", {{"all_arrived_step", 40}})).Reason().has_value());
  EXPECT_FALSE(ExperimentGoal::Judge(SummaryOf("my_kind", nlohmann::json::object())).Reason().has_value());
}

TEST(ExperimentGoalReason, VoronoiCoverageThatNeverSettlesIsJudgedByItsCost) {
  // The shipped voronoi_coverage: 3.20 -> 0.49 m^4, largest rise 0.0003 (blocks moving to the end).
  const ExperimentGoal covering = ExperimentGoal::Judge(SummaryOf(
      "voronoi_coverage", {{"settled_step", -1},
                           {"coverage_cost_initial_m4", 3.20},
                           {"coverage_cost_final_m4", 0.49},
                           {"coverage_cost_max_rise_m4", 0.0003}}));
  EXPECT_TRUE(covering.met);
  EXPECT_EQ(covering.completion_step, -1);
  EXPECT_THAT(covering.detail, HasSubstr("covering, not settled"));
  // The boundaries: half the initial cost, a rise of 1% of it.
  auto met = [](double final_cost, double rise) {
    return ExperimentGoal::Judge(SummaryOf("voronoi_coverage", {{"settled_step", -1},
                                                                {"coverage_cost_initial_m4", 2.0},
                                                                {"coverage_cost_final_m4", final_cost},
                                                                {"coverage_cost_max_rise_m4", rise}}))
        .met;
  };
  EXPECT_TRUE(met(1.0, 0.02));
  EXPECT_FALSE(met(1.01, 0.0));
  EXPECT_FALSE(met(0.5, 0.021));
  // Settled is met whatever the cost did.
  EXPECT_TRUE(ExperimentGoal::Judge(SummaryOf("voronoi_coverage", {{"settled_step", 1147}})).met);
}

}  // namespace
}  // namespace dream::cli
