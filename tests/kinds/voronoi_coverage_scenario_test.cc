// Scenario tests of the thesis's Voronoi coverage experiment (section 3.3):
// each runs a shipped config headless through the same code as `dream run`
// (ControllerFactory -> AgentHost on memq://, SimNode with the Robotarium
// world, RunRecorder) and judges the run from its log with the experiment's
// own metrics (the code that also judges lab runs).
#include <gtest/gtest.h>

#include "scenario_runner.h"

#include <atomic>
#include <cstdio>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/log_metrics.h"
#include "dream/config/config_error.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/node/run_recorder.h"
#include "dream/node/sim_node.h"
#include "dream/world/unicycle_world.h"

namespace dream::agents {
namespace {

using scenario::ConfigPath;
using scenario::RunScenario;
using scenario::ScenarioResult;
using scenario::Value;

// The coverage cost is computed exactly (polygon formulas, no grid), as a
// sum of ~100 terms of at most ~10 m^4: rounding stays below ~1e-13 m^4, so
// any rise above 1e-12 m^4 would be a real rise, not noise.
constexpr double kCostRoundingM4 = 1e-12;
// Robotarium collision: centres 0.025 m ahead, 0.135 m apart; two robots
// facing each other collide below 0.135 + 2 x 0.025 m between centres.
constexpr double kWorstCaseCollisionDistanceM = 0.185;

TEST(VoronoiCoverageScenarioTest, StaticConfigIsTheMovingOneWithoutPaths) {
  const run_config::RunConfig moving = run_config::LoadRunConfigFile(ConfigPath("voronoi_coverage"));
  const run_config::RunConfig still = run_config::LoadRunConfigFile(ConfigPath("voronoi_coverage_static"));
  EXPECT_EQ(still.num_robots, moving.num_robots);
  EXPECT_EQ(still.seed, moving.seed);
  ASSERT_EQ(still.initial_poses.size(), moving.initial_poses.size());
  for (size_t i = 0; i < still.initial_poses.size(); ++i) {
    EXPECT_EQ(still.initial_poses[i].x_m, moving.initial_poses[i].x_m);
    EXPECT_EQ(still.initial_poses[i].y_m, moving.initial_poses[i].y_m);
    EXPECT_EQ(still.initial_poses[i].theta_rad, moving.initial_poses[i].theta_rad);
  }
  ASSERT_EQ(still.obstacles.size(), moving.obstacles.size());
  int moving_count = 0;
  for (size_t k = 0; k < still.obstacles.size(); ++k) {
    EXPECT_EQ(still.obstacles[k].center_m, moving.obstacles[k].center_m);
    EXPECT_EQ(still.obstacles[k].width_m, moving.obstacles[k].width_m);
    EXPECT_EQ(still.obstacles[k].height_m, moving.obstacles[k].height_m);
    EXPECT_FALSE(still.obstacles[k].path.has_value());
    moving_count += moving.obstacles[k].path.has_value() ? 1 : 0;
  }
  EXPECT_EQ(moving_count, 2);  // two large static blocks, two small moving ones
  EXPECT_EQ(still.controller.Keys(), moving.controller.Keys());
}

TEST(VoronoiCoverageScenarioTest, WithoutMovingObstaclesTheCostNeverRisesAndTheRobotsSettle) {
  const ScenarioResult run =
      RunScenario(run_config::LoadRunConfigFile(ConfigPath("voronoi_coverage_static")), "voronoi_coverage_static");
  ASSERT_EQ(run.outcome.end, node::RunOutcome::End::kFinished) << run.outcome.reason;
  EXPECT_EQ(run.outcome.reason, "every robot reported done");
  EXPECT_EQ(run.outcome.robots_done.size(), 15u);
  EXPECT_EQ(run.violations.hard_errors(), 0);

  // The cost is evaluated at every step; its largest step-to-step rise:
  EXPECT_LE(Value(run, "coverage_cost_max_rise_m4"), kCostRoundingM4);
  const double initial = Value(run, "coverage_cost_initial_m4");
  const double final_cost = Value(run, "coverage_cost_final_m4");
  EXPECT_LT(final_cost, 0.2 * initial);  // measured: 3.20 -> 0.47 m^4
  const auto& series = run.metrics.series.at("coverage_cost_m4");
  for (size_t i = 1; i < series.size(); ++i) EXPECT_LE(series[i].second, series[i - 1].second + kCostRoundingM4);

  // Settled: every robot still (< 5 mm/s) from settled_step to the end, >= 30 steps.
  EXPECT_GE(Value(run, "settled_step"), 0.0);
  EXPECT_GE(Value(run, "still_steps_at_end"), 30.0);

  EXPECT_GT(Value(run, "min_pairwise_distance_m"), kWorstCaseCollisionDistanceM);
  EXPECT_EQ(Value(run, "obstacle_contact_steps"), 0.0);
  EXPECT_EQ(run.bad_radio_messages, 0);
}

TEST(VoronoiCoverageScenarioTest, WithMovingObstaclesTheRobotsNeverCollide) {
  const ScenarioResult run =
      RunScenario(run_config::LoadRunConfigFile(ConfigPath("voronoi_coverage")), "voronoi_coverage");
  ASSERT_EQ(run.outcome.end, node::RunOutcome::End::kFinished) << run.outcome.reason;
  EXPECT_EQ(run.outcome.steps, 2000);
  EXPECT_EQ(run.violations.boundary_errors, 0);
  EXPECT_EQ(run.violations.collision_errors, 0);
  EXPECT_EQ(run.violations.obstacle_collisions, 0);
  EXPECT_EQ(run.violations.actuator_errors, 0);
  // Clear by the Robotarium's rule whatever the headings.
  EXPECT_GT(Value(run, "min_pairwise_distance_m"), kWorstCaseCollisionDistanceM);
  EXPECT_EQ(Value(run, "obstacle_contact_steps"), 0.0);
  // Still a coverage: the robots spread out of their corner (measured 3.20 -> 0.49 m^4).
  EXPECT_LT(Value(run, "coverage_cost_final_m4"), 0.2 * Value(run, "coverage_cost_initial_m4"));
  EXPECT_EQ(run.bad_radio_messages, 0);
}

std::string ConfigErrorOf(const std::string& section_text) {
  try {
    agent_host::ControllerFactory(config::ConfigNode::LoadString(section_text, "c.yaml"), 15, 1);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(VoronoiCoverageConfigTest, MistakesNameTheKeyAndItsLine) {
  EXPECT_NE(ConfigErrorOf("kind: voronoi_coverage\nrobot_buffer_m: -0.1\n").find("c.yaml:2: robot_buffer_m: "),
            std::string::npos);
  EXPECT_NE(ConfigErrorOf("kind: voronoi_coverage\ngain: 1\nmax_speed_mps: 0.5\n").find("c.yaml:3: max_speed_mps: "),
            std::string::npos);
  EXPECT_NE(
      ConfigErrorOf("kind: voronoi_coverage\ncoverage_sample_steps: 0\n").find("c.yaml:2: coverage_sample_steps: "),
      std::string::npos);
  EXPECT_NE(ConfigErrorOf("kind: voronoi_coverage\ntolerance: 0.03\n").find("unknown key for kind voronoi_coverage"),
            std::string::npos);
  EXPECT_EQ(ConfigErrorOf("kind: voronoi_coverage\n"), "");  // every key has a default
}

}  // namespace
}  // namespace dream::agents
