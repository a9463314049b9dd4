// A controller kind that is one Robot subclass (ControllerKind::OfRobot):
// registered with one line, its own keys read by the robot's constructor and
// checked when the config is read, the common parts (robot timer and gains,
// sensors, radio) from the config, no metrics of its own but the safety
// ones, and a run over memq as `dream run` does it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/kind_api/controller_kind.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/config/config_error.h"
#include "dream/run_config/run_config.h"
#include "../support/factory_error.h"
#include "scenario_runner.h"  // tests/kinds

namespace dream::agents {
namespace {

/// Drives straight ahead at its own entry of `speeds_mps` (one per robot).
class CruiseRobot final : public Robot {
 public:
  CruiseRobot(int id, const RobotParams& params, const config::ConfigNode& section)
      : Robot(id, params), speed_mps_(ReadSpeed(section, id)) {}

  UnicycleCommand Update(int64_t /*step*/) override { return LimitActuators({speed_mps_, 0.0}); }

  double speed_mps() const { return speed_mps_; }
  const RobotParams& robot_params() const { return params(); }

 private:
  static double ReadSpeed(const config::ConfigNode& section, int id) {
    const config::ConfigNode speeds = section.Required("speeds_mps");
    if (!speeds.IsSequence() || speeds.size() <= static_cast<size_t>(id)) {
      speeds.Fail("expected one speed per robot, robot " + std::to_string(id) + " has none");
    }
    const config::ConfigNode mine = speeds[static_cast<size_t>(id)];
    const double speed_mps = mine.AsDouble();
    if (speed_mps < 0.0) mine.Fail("must be >= 0, got " + std::to_string(speed_mps));
    return speed_mps;
  }

  double speed_mps_;
};

/// Reads no keys: the builder uses the (id, params) constructor.
class ParkedRobot final : public Robot {
 public:
  using Robot::Robot;
  UnicycleCommand Update(int64_t /*step*/) override { return {}; }
};

/// Brings the optional static members ControllerKind::OfRobot reads.
class ChattyRobot final : public Robot {
 public:
  static constexpr bool kGraphMustConnect = true;
  static kind_api::AgentPartsConfig DefaultParts(int num_robots) {
    kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::Defaults(num_robots);
    parts.robot_period_steps.assign(static_cast<size_t>(num_robots), 5);
    return parts;
  }
  using Robot::Robot;
  UnicycleCommand Update(int64_t /*step*/) override { return {}; }
};

// The in-tree way: one line adding the kind (controller_registry.cc adds the
// built-in ones the same way), here to a registry of this test's own.
std::shared_ptr<const agent_host::ControllerRegistry> TestKinds() {
  static const std::shared_ptr<const agent_host::ControllerRegistry> kinds = [] {
    auto registry = std::make_shared<agent_host::ControllerRegistry>();
    registry->AddAll(agent_host::ControllerRegistry::BuiltIns(), "built in");
    registry->Add(kind_api::ControllerKind::OfRobot<CruiseRobot>("test_cruise", {"speeds_mps"}), "this test");
    registry->Add(kind_api::ControllerKind::OfRobot<ParkedRobot>("test_parked", {}), "this test");
    return registry;
  }();
  return kinds;
}

/// A two-robot run config whose `controller:` section is `controller` (YAML
/// flow map text), on line 5 of test.yaml.
run_config::RunConfig Config(const std::string& controller, int steps = 60) {
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(
      "name: t\nrobots: 2\nsteps: " + std::to_string(steps) +
          "\ninitial_poses: [[-1.0, -0.4, 0.0], [-1.0, 0.4, 0.0]]\ncontroller: " + controller + "\n",
      "test.yaml"));
}

using testing::FactoryErrorOf;

const CruiseRobot& CruiseOf(const RobotAgent& agent) { return dynamic_cast<const CruiseRobot&>(agent.robot()); }

TEST(RobotClassKindTest, ARobotClassRegisteredWithOneLineRunsWithItsOwnKeys) {
  const run_config::RunConfig config = Config("{kind: test_cruise, speeds_mps: [0.1, 0.05]}");
  const agent_host::ControllerFactory factory(config, TestKinds());
  EXPECT_EQ(factory.kind(), "test_cruise");
  EXPECT_EQ(CruiseOf(*factory.Make(0)).speed_mps(), 0.1);
  EXPECT_EQ(CruiseOf(*factory.Make(1)).speed_mps(), 0.05);
  // No metrics of its own: only the safety metrics every kind gets.
  EXPECT_EQ(factory.MakeMetrics().size(), 1u);

  const scenario::ScenarioResult run = scenario::RunScenario(config, "robot_class_kind", TestKinds());
  EXPECT_EQ(run.outcome.steps, config.sim.max_steps);
  EXPECT_GT(scenario::Value(run, "min_pairwise_distance_m"), 0.7);
  const double step_s = config.world.time_step_s;
  for (size_t id = 0; id < 2; ++id) {
    const double speed_mps = id == 0 ? 0.1 : 0.05;
    const world::Pose2& start = config.initial_poses[id];
    const world::Pose2& end = run.final_poses[id];
    // Each robot drove straight at its own speed for the run, give or take the
    // step it waits for its first odometry.
    EXPECT_NEAR(end.x_m - start.x_m, speed_mps * step_s * static_cast<double>(config.sim.max_steps),
                2.0 * speed_mps * step_s)
        << "robot " << id;
    EXPECT_NEAR(end.y_m, start.y_m, 1e-9) << "robot " << id;
  }
}

TEST(RobotClassKindTest, TheCommonPartsComeFromTheConfig) {
  const run_config::RunConfig config = Config(
      "{kind: test_cruise, speeds_mps: [0.1, 0.1], robot: {vel_gain: 0.5, start_delay_steps: [0, 30]}, "
      "sensors: [{kind: odometry}, {kind: movement, range_m: 2.0}], radio: {kind: range, range_m: 1.0}}");
  const agent_host::ControllerFactory factory(config, TestKinds());
  EXPECT_EQ(CruiseOf(*factory.Make(0)).robot_params().vel_gain, 0.5);
  const scenario::ScenarioResult run = scenario::RunScenario(config, "robot_class_kind_parts", TestKinds());
  const double early_m = run.final_poses[0].x_m - config.initial_poses[0].x_m;
  const double late_m = run.final_poses[1].x_m - config.initial_poses[1].x_m;
  // Robot 1's timer starts 30 steps later: it drove 30 steps' worth less.
  EXPECT_NEAR(early_m - late_m, 0.1 * config.world.time_step_s * 30.0, 0.1 * config.world.time_step_s);

  // A part's own mistakes are reported as for the shipped kinds.
  const std::string error =
      FactoryErrorOf(TestKinds(), Config("{kind: test_cruise, speeds_mps: [0.1, 0.1], radio: {kind: carrier}}"));
  EXPECT_NE(error.find("controller.radio.kind: unknown radio kind 'carrier'"), std::string::npos) << error;
}

TEST(RobotClassKindTest, AnUnknownKeyIsRefusedNamingFileLineAndKey) {
  const std::string error =
      FactoryErrorOf(TestKinds(), Config("{kind: test_cruise, speeds_mps: [0.1, 0.1], speed_mps: 0.1}"));
  EXPECT_EQ(error,
            "test.yaml:5: controller.speed_mps: unknown key for kind test_cruise "
            "(did you mean 'speeds_mps'?); allowed keys here: kind, robot, "
            "sensors, radio, speeds_mps");
  // A class that reads no keys takes none.
  const std::string parked = FactoryErrorOf(TestKinds(), Config("{kind: test_parked, speeds_mps: [0.1, 0.1]}"));
  EXPECT_EQ(parked,
            "test.yaml:5: controller.speeds_mps: unknown key for kind test_parked; allowed keys here: kind, robot, "
            "sensors, radio");
  EXPECT_EQ(FactoryErrorOf(TestKinds(), Config("{kind: test_parked}")), "");
}

TEST(RobotClassKindTest, TheRobotsBadValuesStopTheFactoryNotALaterAgent) {
  // Robot 1's entry is wrong: the factory refuses the config before any Make().
  const std::string negative =
      FactoryErrorOf(TestKinds(), Config("{kind: test_cruise,\n  speeds_mps: [0.1,\n    -1]}"));
  EXPECT_EQ(negative.rfind("test.yaml:7: controller.speeds_mps[1]: must be >= 0, got -1", 0), 0u) << negative;
  const std::string short_list = FactoryErrorOf(TestKinds(), Config("{kind: test_cruise, speeds_mps: [0.1]}"));
  EXPECT_EQ(short_list, "test.yaml:5: controller.speeds_mps: expected one speed per robot, robot 1 has none");
  const std::string missing = FactoryErrorOf(TestKinds(), Config("{kind: test_cruise}"));
  EXPECT_EQ(missing, "test.yaml:5: controller.speeds_mps: missing; this key is required");
}

TEST(RobotClassKindTest, AMissingOrUnknownKindIsAClearError) {
  const std::string missing = FactoryErrorOf(TestKinds(), Config("{speeds_mps: [0.1, 0.1]}"));
  EXPECT_EQ(missing, "test.yaml:5: controller.kind: missing; this key is required");
  const std::string unknown = FactoryErrorOf(TestKinds(), Config("{kind: test_cruse, speeds_mps: [0.1, 0.1]}"));
  EXPECT_EQ(unknown.rfind("test.yaml:5: controller.kind: unknown controller kind 'test_cruse' "
                          "(did you mean 'test_cruise'?); known kinds: "
                          "go_to_goal",
                          0),
            0u)
      << unknown;
  EXPECT_NE(unknown.find(", test_cruise"), std::string::npos) << "the registered kind is listed: " << unknown;
}

TEST(RobotClassKindTest, OfRobotReadsTheClassesOptionalStaticMembers) {
  const kind_api::ControllerKind chatty = kind_api::ControllerKind::OfRobot<ChattyRobot>("chatty", {"a"});
  EXPECT_EQ(chatty.name, "chatty");
  EXPECT_EQ(chatty.keys, std::vector<std::string>{"a"});
  EXPECT_TRUE(chatty.graph_must_connect);
  EXPECT_EQ(chatty.default_parts(3).robot_period_steps, (std::vector<int>{5, 5, 5}));
  // Without them: the defaults of every kind.
  const kind_api::ControllerKind parked = kind_api::ControllerKind::OfRobot<ParkedRobot>("parked", {});
  EXPECT_FALSE(parked.graph_must_connect);
  EXPECT_EQ(parked.default_parts(2).robot_period_steps, kind_api::AgentPartsConfig::Defaults(2).robot_period_steps);
  const std::unique_ptr<kind_api::ExperimentBuilder> builder = parked.make_builder(config::ConfigNode(), 2);
  EXPECT_EQ(builder->MakeRobot(1, RobotParams())->id(), 1);
  EXPECT_EQ(builder->MakeMetrics(), nullptr);
}

}  // namespace
}  // namespace dream::agents
