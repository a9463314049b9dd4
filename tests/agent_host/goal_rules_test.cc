// Each experiment kind's own success rule (ExperimentMetrics::JudgeGoal),
// reached the way a run reaches it: through the ControllerFactory of the
// shipped config, on figures as its metrics write them. And its goals to draw
// (ExperimentBuilder::GoalsToDraw). Nothing here names a rule outside its kind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <optional>

#include "dream/agent_host/controller_factory.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "../support/source_tree.h"

namespace dream::agents {
namespace {

using ::testing::HasSubstr;

/// The judgement of the shipped config `name` on `values`: the first of its
/// metrics with a rule (the kind's own come first), or nothing.
std::optional<GoalJudgement> Judge(const std::string& name, const std::map<std::string, double>& values) {
  const run_config::RunConfig config =
      run_config::LoadRunConfigFile(dream::testing::SourceDir() + "/config/" + name + ".yaml");
  const agent_host::ControllerFactory factory(config);
  MetricsReport report;
  report.values = values;
  for (const auto& metrics : factory.MakeMetrics()) {
    if (std::optional<GoalJudgement> goal = metrics->JudgeGoal(report)) return goal;
  }
  return std::nullopt;
}

TEST(GoalRules, GoToGoalIsMetWhenEveryRobotArrivedAtOnce) {
  const auto met = Judge("go_to_goal", {{"all_arrived_step", 400}, {"final_max_goal_error_m", 0.01}});
  ASSERT_TRUE(met);
  EXPECT_TRUE(met->met);
  EXPECT_EQ(met->completion_step, 400);
  const auto missed = Judge("go_to_goal", {{"all_arrived_step", -1}, {"final_max_goal_error_m", 0.2}});
  ASSERT_TRUE(missed);
  EXPECT_FALSE(missed->met);
  // The goal's tolerance (goal_tolerance_m: 0.05), not where the robots stop (tolerance_m: 0.02).
  EXPECT_EQ(missed->detail,
            "not all at their goals, worst 0.2 m on the logged poses (tolerance 0.05 m, compared unrounded)");
  // Missed by a hair: enough digits that the worst does not read as the tolerance.
  const auto hair = Judge("go_to_goal", {{"all_arrived_step", -1}, {"final_max_goal_error_m", 0.0500082}});
  ASSERT_TRUE(hair);
  EXPECT_EQ(hair->detail,
            "not all at their goals, worst 0.05001 m on the logged poses (tolerance 0.05 m, compared unrounded)");
}

/// Two robots 3 cm from their goals, stopping at 2 cm, judged at `goal_tolerance`
/// (a YAML number, or nothing: tolerance_m).
std::optional<GoalJudgement> GoToGoalAtThreeCentimetres(const std::string& goal_tolerance) {
  const std::string text =
      "name: two\nrobots: 2\nsteps: 10\ninitial_poses: [[0, 0, 0], [0.5, 0, 0]]\n"
      "controller:\n  kind: go_to_goal\n  tolerance_m: 0.02\n"
      "  goals: [[0.03, 0], [0.5, 0.03]]\n" +
      (goal_tolerance.empty() ? std::string() : "  goal_tolerance_m: " + goal_tolerance + "\n");
  const run_config::RunConfig config = run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "two.yaml"));
  const agent_host::ControllerFactory factory(config);
  auto metrics = std::move(factory.MakeMetrics().front());
  WorldSnapshot world;
  world.step = 5;
  world.poses = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0, 0)};
  world.velocities.assign(2, Eigen::Vector2d::Zero());
  metrics->Observe(world);
  MetricsReport report;
  metrics->Write(&report);
  return metrics->JudgeGoal(report);
}

// The goal is judged at goal_tolerance_m, apart from where robots stop (tolerance_m).
TEST(GoalRules, GoToGoalIsJudgedAtItsGoalToleranceNotWhereRobotsStop) {
  const auto stop_line = GoToGoalAtThreeCentimetres("");
  ASSERT_TRUE(stop_line);
  EXPECT_FALSE(stop_line->met);
  EXPECT_EQ(stop_line->detail,
            "not all at their goals, worst 0.03 m on the logged poses (tolerance 0.02 m, compared unrounded)");
  const auto goal_line = GoToGoalAtThreeCentimetres("0.05");
  ASSERT_TRUE(goal_line);
  EXPECT_TRUE(goal_line->met);
  EXPECT_EQ(goal_line->completion_step, 5);
}

TEST(GoalRules, MetresApartPrintsTheDigitsThatTellAValueFromItsReference) {
  EXPECT_EQ(GoalJudgement::MetresApart(0.0200082, 0.02), "0.02001 m");
  EXPECT_EQ(GoalJudgement::MetresApart(0.02, 0.0199999999), "0.02 m");
  EXPECT_EQ(GoalJudgement::MetresApart(0.0123456, 0.02), "0.0123 m");  // far apart: three digits
  EXPECT_EQ(GoalJudgement::MetresApart(0.02, 0.02), "0.02 m");
}

TEST(GoalRules, HrvoCircleCountsItsFormations) {
  const auto missed = Judge("hrvo_circle", {{"formations_completed", 2},
                                            {"formation_1_completed_step", 100},
                                            {"formation_2_completed_step", 200},
                                            {"formation_3_completed_step", -1},
                                            {"all_formations_completed_step", -1}});
  ASSERT_TRUE(missed);
  EXPECT_FALSE(missed->met);
  EXPECT_EQ(missed->detail, "2 of 3 formations");
  const auto met = Judge("hrvo_circle", {{"formations_completed", 3},
                                         {"formation_1_completed_step", 100},
                                         {"formation_2_completed_step", 200},
                                         {"formation_3_completed_step", 1985},
                                         {"all_formations_completed_step", 1985}});
  ASSERT_TRUE(met);
  EXPECT_TRUE(met->met);
  EXPECT_EQ(met->completion_step, 1985);
}

TEST(GoalRules, LineDeploymentIsMetOnceConverged) {
  const auto met = Judge("line_deployment", {{"converged_step", 700}});
  ASSERT_TRUE(met);
  EXPECT_TRUE(met->met);
  EXPECT_EQ(met->completion_step, 700);
  const auto missed =
      Judge("line_deployment",
            {{"converged_step", -1}, {"final_line_straightness_error_m", 0.05}, {"final_spacing_error_m", 0.02}});
  ASSERT_TRUE(missed);
  EXPECT_FALSE(missed->met);
  EXPECT_THAT(missed->detail, HasSubstr("straightness 0.05 m, spacing 0.02 m"));
}

TEST(GoalRules, VoronoiCoverageSettlesOrElseIsJudgedByItsCost) {
  EXPECT_TRUE(Judge("voronoi_coverage", {{"settled_step", 1147}})->met);
  // The shipped voronoi_coverage: 3.20 -> 0.49 m^4, largest rise 0.0003 (blocks moving to the end).
  const auto covering = Judge("voronoi_coverage", {{"settled_step", -1},
                                                   {"coverage_cost_initial_m4", 3.20},
                                                   {"coverage_cost_final_m4", 0.49},
                                                   {"coverage_cost_max_rise_m4", 0.0003}});
  ASSERT_TRUE(covering);
  EXPECT_TRUE(covering->met);
  EXPECT_EQ(covering->completion_step, -1);
  EXPECT_THAT(covering->detail, HasSubstr("covering, not settled"));
  // The boundaries: half the initial cost, a rise of 1% of it.
  auto met = [](double final_cost, double rise) {
    return Judge("voronoi_coverage_static", {{"settled_step", -1},
                                             {"coverage_cost_initial_m4", 2.0},
                                             {"coverage_cost_final_m4", final_cost},
                                             {"coverage_cost_max_rise_m4", rise}})
        ->met;
  };
  EXPECT_TRUE(met(1.0, 0.02));
  EXPECT_FALSE(met(1.01, 0.0));
  EXPECT_FALSE(met(0.5, 0.021));
}

TEST(GoalRules, AffineFormationKeepsItsFollowersWithinTheTolerance) {
  const auto met = Judge(
      "affine_formation",
      {{"max_follower_error_after_convergence_m", 0.02}, {"follower_error_tolerance_m", 0.05}, {"settled_step", 557}});
  ASSERT_TRUE(met);
  EXPECT_TRUE(met->met);
  EXPECT_EQ(met->completion_step, 557);
  const auto missed = Judge("affine_formation",
                            {{"max_follower_error_after_convergence_m", 0.08}, {"follower_error_tolerance_m", 0.05}});
  ASSERT_TRUE(missed);
  EXPECT_FALSE(missed->met);
  EXPECT_EQ(missed->detail, "worst follower error 0.08 m > 0.05 m");
}

TEST(GoalRules, CalibrationDriveIsMetWhenItsProgramRanToItsEndClean) {
  const auto met = Judge("calibration", {{"calibration_program_steps", 1480},
                                         {"calibration_last_step", 1480},
                                         {"boundary_error_steps", 0},
                                         {"collision_steps", 0}});
  ASSERT_TRUE(met);
  EXPECT_TRUE(met->met);
  EXPECT_EQ(met->completion_step, 1480);
  const auto collided = Judge("calibration", {{"calibration_program_steps", 1480},
                                              {"calibration_last_step", 1480},
                                              {"boundary_error_steps", 0},
                                              {"collision_steps", 2},
                                              {"first_collision_step", 900}});
  ASSERT_TRUE(collided);
  EXPECT_FALSE(collided->met);
  EXPECT_THAT(collided->detail, HasSubstr("2 with a collision (first 900)"));
}

TEST(GoalRules, KindsWithGoalsToDrawGiveOnePerRobot) {
  auto goals_of = [](const std::string& name) {
    const run_config::RunConfig config =
        run_config::LoadRunConfigFile(dream::testing::SourceDir() + "/config/" + name + ".yaml");
    return std::make_pair(agent_host::ControllerFactory(config).GoalsToDraw(), config.num_robots);
  };
  const auto [go_to_goal, go_to_goal_robots] = goals_of("go_to_goal");
  ASSERT_EQ(go_to_goal.size(), static_cast<size_t>(go_to_goal_robots));
  EXPECT_EQ(go_to_goal[0].size(), 1U);
  const auto [circle, circle_robots] = goals_of("hrvo_circle");
  ASSERT_EQ(circle.size(), static_cast<size_t>(circle_robots));
  EXPECT_EQ(circle[0].size(), 3U);                         // one point per formation
  EXPECT_TRUE(goals_of("line_deployment").first.empty());  // a line, not points: nothing to mark
}

}  // namespace
}  // namespace dream::agents
