// Scenario and config tests of the thesis's affine formation maneuver
// (section 3.4, config/affine_formation.yaml): the shipped config runs
// headless through the same code as `dream run` (ControllerFactory ->
// AgentHost on memq://, SimNode with the Robotarium world, RunRecorder) and
// is judged from its log by the experiment's own metrics, the code that also
// judges lab runs.
#include <gtest/gtest.h>

#include "scenario_runner.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/log_metrics.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/node/run_recorder.h"
#include "dream/node/sim_node.h"
#include "dream/world/unicycle_world.h"
#include "../support/source_tree.h"

namespace dream::agents {
namespace {

using scenario::ConfigPath;
using scenario::RunScenario;
using scenario::ScenarioResult;
using scenario::Value;

const std::string kConfigPath = dream::testing::SourceDir() + "/config/affine_formation.yaml";

std::string ConfigText() {
  std::ifstream in(kConfigPath);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The config with `from` replaced by `to` (which must occur exactly once).
std::string Edited(const std::string& from, const std::string& to) {
  std::string text = ConfigText();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

run_config::RunConfig Load(const std::string& text) {
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "affine_formation.yaml"));
}

// What the experiment must show, whatever the noise: the followers arrive
// before the maneuver starts at step 900 and from then to the end stay within
// 5 cm of the affine image the leaders define; both gates pass (gate A while
// the formation is flattened, steps 1100-1700; gate B while it is a line,
// 2300-3150) without touching anyone; no robot collision, no boundary error.
void ExpectSuccess(const ScenarioResult& run) {
  EXPECT_EQ(run.outcome.end, node::RunOutcome::End::kFinished) << run.outcome.reason;
  EXPECT_EQ(run.outcome.steps, 3650);
  EXPECT_EQ(run.violations.boundary_errors, 0);
  EXPECT_EQ(run.violations.collision_errors, 0);
  EXPECT_EQ(run.violations.obstacle_collisions, 0);
  EXPECT_EQ(Value(run, "convergence_window_start_step"), 900);
  EXPECT_LT(Value(run, "max_follower_error_after_convergence_m"), 0.05);
  const double settled = Value(run, "settled_step");
  EXPECT_GE(settled, 0);
  EXPECT_LE(settled, 900);
  EXPECT_EQ(Value(run, "leader_fit_failures"), 0);
  for (int pair = 0; pair < 2; ++pair) {
    const std::string name = "obstacle_pair_" + std::to_string(pair) + "_";
    EXPECT_GT(Value(run, name + "min_clearance_m"), 0.0) << name;
    EXPECT_EQ(Value(run, name + "contact_steps"), 0) << name;
  }
  const double passage_a = Value(run, "obstacle_pair_0_passage_step");
  const double passage_b = Value(run, "obstacle_pair_1_passage_step");
  EXPECT_TRUE(passage_a > 1100 && passage_a < 1700) << passage_a;
  EXPECT_TRUE(passage_b > 2300 && passage_b < 3150) << passage_b;
  EXPECT_EQ(run.bad_radio_messages, 0);
}

TEST(AffineFormationScenarioTest, ShippedConfigTracksWithin5cmAndPassesBothGates) {
  const ScenarioResult run = RunScenario(run_config::LoadRunConfigFile(kConfigPath), "affine_formation");
  ExpectSuccess(run);
  // The shipped run, measured: max follower error 2.0 cm after step 900,
  // settled from step 557, clearances 0.128 m (gate A) and 0.091 m (gate B).
  EXPECT_LT(Value(run, "max_follower_error_after_convergence_m"), 0.03);
  EXPECT_GT(Value(run, "min_pairwise_distance_m"), 0.17);
}

TEST(AffineFormationScenarioTest, NoisySensorsStillTrackAndPass) {
  // 2 mm / 2 mrad of odometry and movement-sensor noise, another seed.
  run_config::RunConfig config =
      Load(Edited("  kind: affine_formation\n",
                  "  kind: affine_formation\n"
                  "  sensors: [{kind: odometry, noise_std: 0.002}, {kind: movement, noise_std: 0.002}]\n"));
  config.seed = 4;
  ExpectSuccess(RunScenario(config, "affine_formation_noisy"));
}

std::string ConfigError(const std::string& text) {
  try {
    const run_config::RunConfig config = Load(text);
    agent_host::ControllerFactory factory(config.controller, config.num_robots, config.seed);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no config error";
  return "";
}

const char* const kRow3 = "      - [-0.137, 0.5482, 0, 0, 0.0685, 0.2741, 0]\n";

TEST(AffineFormationConfigTest, BadStressMatrixNamesTheKey) {
  // A short row.
  std::string error = ConfigError(Edited(kRow3, "      - [-0.137, 0.5482, 0, 0, 0.0685, 0.2741]\n"));
  EXPECT_NE(error.find("controller.radio.graph[3]"), std::string::npos) << error;
  EXPECT_NE(error.find("7x7"), std::string::npos) << error;
  // A non-finite weight.
  error = ConfigError(Edited(kRow3, "      - [-0.137, 0.5482, 0, 0, .nan, 0.2741, 0]\n"));
  EXPECT_NE(error.find("controller.radio.graph[3]"), std::string::npos) << error;
  // Too few rows.
  error = ConfigError(Edited("      - [0, -0.137, 0, 0, 0.2741, 0.137, 0]\n", ""));
  EXPECT_NE(error.find("controller.radio.graph"), std::string::npos) << error;
  // Not symmetric.
  error = ConfigError(Edited(kRow3, "      - [-0.137, 0.5482, 0, 0, 0.0685, 0.3, 0]\n"));
  EXPECT_NE(error.find("controller.radio.graph: stress weights: a stress is symmetric"), std::string::npos) << error;
  // Symmetric, but not an equilibrium stress of the nominal positions.
  error = ConfigError(Edited("    - [-0.6, 0.4]\n", "    - [-0.5, 0.4]\n"));
  EXPECT_NE(error.find("controller.radio.graph: stress weights: not an equilibrium stress of nominal_positions"),
            std::string::npos)
      << error;
}

TEST(AffineFormationConfigTest, OtherMistakesNameTheirKeys) {
  std::string error = ConfigError(Edited("    kind: role\n", "    kind: graph\n"));
  EXPECT_NE(error.find("controller.radio.kind"), std::string::npos) << error;
  error = ConfigError(Edited("    - [0.6, 0.0]\n", ""));
  EXPECT_NE(error.find("controller.nominal_positions"), std::string::npos) << error;
  // Squeezed so hard that two targets come within 0.28 m.
  error = ConfigError(Edited("    - {step: 1100, scale_y: 0.45,", "    - {step: 1100, scale_y: 0.2,"));
  EXPECT_NE(error.find("controller.maneuver"), std::string::npos) << error;
  EXPECT_NE(error.find("min_target_spacing_m"), std::string::npos) << error;
  error = ConfigError(Edited("law: zhao,", "law: fast,"));
  EXPECT_NE(error.find("controller.follower.law"), std::string::npos) << error;
  error = ConfigError(Edited("  drive: reversible", "  drive: sideways"));
  EXPECT_NE(error.find("controller.drive"), std::string::npos) << error;
}

// The plan is checked before the run: every step of a segment up to 1024
// steps long, and a longer segment at 1024 evenly spaced steps, so a keyframe
// at step 10^12 is checked at once (it hung `dream run` before) and a target
// leaving the arena midway is still found.
TEST(AffineFormationConfigTest, ManeuversOfAnyLengthAreCheckedWithBoundedWork) {
  const std::string last = "    - {step: 3550, translation: [0.3, 0.0]}";
  const run_config::RunConfig long_plan = Load(Edited(last, "    - {step: 1000000000000, translation: [0.3, 0.0]}"));
  EXPECT_NO_THROW(agent_host::ControllerFactory(long_plan.controller, long_plan.num_robots, long_plan.seed));
  const std::string error = ConfigError(Edited(last, "    - {step: 1000000000000, translation: [3.0, 0.0]}"));
  EXPECT_NE(error.find("controller.maneuver: at step "), std::string::npos) << error;
  EXPECT_NE(error.find("is not 0.1 m inside the arena"), std::string::npos) << error;
  // Robot 0 passes x = 1.5 about 30% of the way through the last segment
  // (step 2.96e11 of 1e12): found there, not at the segment's end.
  const long long step = std::stoll(error.substr(error.find("at step ") + 8));
  EXPECT_GT(step, 2.0e11) << error;
  EXPECT_LT(step, 4.0e11) << error;

  std::string frames;
  for (int k = 0; k <= 1000; ++k) frames += "    - {step: " + std::to_string(k) + "}\n";
  const std::string too_many =
      ConfigError(Edited("    - {step: 0}                                    "
                         "# stand still while the followers arrive\n",
                         frames));
  EXPECT_NE(too_many.find("controller.maneuver: at most 1000 keyframes, got 1008"), std::string::npos) << too_many;
}

}  // namespace
}  // namespace dream::agents
