#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/controller_plugin.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/config/config_error.h"
#include "dream/run_config/run_config.h"
#include "../support/factory_error.h"

namespace dream::agents {
namespace {

namespace fs = std::filesystem;

/// A one-robot run config naming `plugins` (YAML list text) and `kind`.
run_config::RunConfig Config(const std::string& plugins, const std::string& kind = "test_still",
                             const std::string& source = "test.yaml") {
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(
      "name: t\nrobots: 1\ninitial_poses: [[0, 0, 0]]\nplugins: " + plugins + "\ncontroller: {kind: " + kind + "}\n",
      source));
}

using testing::FactoryErrorOf;

bool Knows(const std::string& kind) {
  const std::vector<std::string> kinds = agent_host::ControllerFactory::Kinds();
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

std::string Quoted(const std::string& path) { return "'" + path + "'"; }

TEST(ControllerPluginTest, AGoodPluginAddsItsKindOnceHoweverOftenItIsNamed) {
  EXPECT_FALSE(Knows("test_still"));
  const run_config::RunConfig config =
      Config("[" + Quoted(TEST_PLUGIN_GOOD_PATH) + ", " + Quoted(TEST_PLUGIN_GOOD_PATH) + "]");
  const agent_host::ControllerFactory factory(config);
  EXPECT_EQ(factory.kind(), "test_still");
  // The kind is the factory's: loading the plugin changed no registry others share.
  EXPECT_FALSE(Knows("test_still"));
  EXPECT_NE(factory.Make(0), nullptr);
  EXPECT_EQ(factory.MakeMetrics().size(), 2u);  // the plugin's and the safety metrics
  // Its metrics' success rule and goals to draw reach the tools as a built-in kind's do
  // (agent_host::MetricsFromLog runs this loop over a run's log).
  agents::MetricsReport report;
  const auto metrics = factory.MakeMetrics();
  for (const auto& m : metrics) m->Write(&report);
  std::optional<agents::GoalJudgement> goal;
  for (const auto& m : metrics) {
    if (!goal) goal = m->JudgeGoal(report);
  }
  ASSERT_TRUE(goal.has_value());
  EXPECT_TRUE(goal->met);
  EXPECT_EQ(goal->detail, "held still");
  ASSERT_EQ(factory.GoalsToDraw().size(), 1u);
  EXPECT_EQ(factory.GoalsToDraw()[0].at(0), Eigen::Vector2d(0.25, -0.5));
  // Another factory (dream run builds several) loads nothing twice.
  EXPECT_EQ(FactoryErrorOf(config), "");
  // The kind's own keys are checked like a built-in kind's.
  const run_config::RunConfig typo = run_config::LoadRunConfig(config::ConfigNode::LoadString(
      "name: t\nrobots: 1\ninitial_poses: [[0, 0, 0]]\nplugins: [" + Quoted(TEST_PLUGIN_GOOD_PATH) +
          "]\ncontroller: {kind: test_still, patience: 2}\n",
      "test.yaml"));
  EXPECT_NE(FactoryErrorOf(typo).find("controller.patience: unknown key for kind test_still "
                                      "(did you mean 'patience_s'?); allowed keys here: kind, "
                                      "robot, sensors, radio, patience_s"),
            std::string::npos)
      << FactoryErrorOf(typo);
}

TEST(ControllerPluginTest, ARobotClassPluginAddsAKindWithoutMetricsOrKeysOfItsOwn) {
  EXPECT_FALSE(Knows("test_parked"));
  const run_config::RunConfig config = Config("[" + Quoted(TEST_PLUGIN_ROBOT_PATH) + "]", "test_parked");
  const agent_host::ControllerFactory factory(config);
  EXPECT_FALSE(Knows("test_parked"));  // the factory's kind, not a global one
  ASSERT_NE(factory.Make(0), nullptr);
  EXPECT_EQ(factory.Make(0)->robot().id(), 0);
  EXPECT_EQ(factory.MakeMetrics().size(), 1u);  // the safety metrics only
  const std::string error = FactoryErrorOf(Config("[" + Quoted(TEST_PLUGIN_ROBOT_PATH) + "]", "test_parked, gain: 1"));
  EXPECT_NE(error.find("test.yaml:5: controller.gain: unknown key for kind test_parked; allowed keys here: kind, "
                       "robot, sensors, radio"),
            std::string::npos)
      << error;
}

TEST(ControllerPluginTest, AnUnknownKindPointsAtPlugins) {
  const std::string error = FactoryErrorOf(Config("[]", "test_elsewhere"));
  EXPECT_NE(error.find("unknown controller kind 'test_elsewhere'; known kinds: go_to_goal"), std::string::npos)
      << error;
  EXPECT_NE(error.find("needs the plugin under `plugins:`"), std::string::npos) << error;
}

TEST(ControllerPluginTest, AMissingFileNamesTheEntryAndThePath) {
  const std::string error = FactoryErrorOf(Config("[nowhere/libmissing.so]", "test_still", "configs/exp.yaml"));
  const std::string expected_path = (fs::absolute("configs") / "nowhere/libmissing.so").lexically_normal().string();
  EXPECT_EQ(error.rfind("configs/exp.yaml:4: plugins[0]: " + expected_path + ": no such file", 0), 0u) << error;
}

TEST(ControllerPluginTest, AFileThatIsNoLibraryQuotesTheLoader) {
  const fs::path fake = fs::temp_directory_path() / ("dream_not_a_plugin_" + std::to_string(::getpid()) + ".so");
  std::ofstream(fake) << "not an ELF file\n";
  const std::string error = FactoryErrorOf(Config("[" + Quoted(fake.string()) + "]"));
  fs::remove(fake);
  EXPECT_NE(error.find("plugins[0]: " + fake.string() + ": cannot load it: " + fake.string()), std::string::npos)
      << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
}

TEST(ControllerPluginTest, ALibraryWithoutEntryPointsIsRefused) {
  const std::string error = FactoryErrorOf(Config("[" + Quoted(TEST_PLUGIN_NO_ENTRY_PATH) + "]"));
  EXPECT_NE(error.find(std::string("plugins[0]: ") + TEST_PLUGIN_NO_ENTRY_PATH +
                       ": not a dream controller plugin: it has no dream_plugin_api_version()"),
            std::string::npos)
      << error;
}

TEST(ControllerPluginTest, APluginWithAnotherCopyOfTheDreamLibrariesIsRefused) {
  const std::string error = FactoryErrorOf(Config("[" + Quoted(TEST_PLUGIN_FOREIGN_PATH) + "]"));
  EXPECT_NE(error.find(std::string(TEST_PLUGIN_FOREIGN_PATH) + ": it uses another copy of the dream libraries (" +
                       TEST_PLUGIN_FOREIGN_PATH + "); rebuild it against the dream that loads it"),
            std::string::npos)
      << error;
}

TEST(ControllerPluginTest, APluginForAnotherApiVersionIsRefusedBeforeItRegisters) {
  const std::string error = FactoryErrorOf(Config("[" + Quoted(TEST_PLUGIN_OLD_API_PATH) + "]", "test_old"));
  EXPECT_NE(error.find(std::string(TEST_PLUGIN_OLD_API_PATH) + ": built for dream plugin API 0, this dream has API " +
                       std::to_string(DREAM_PLUGIN_API_VERSION) + "; rebuild it"),
            std::string::npos)
      << error;
  EXPECT_FALSE(Knows("test_old"));
}

TEST(ControllerPluginTest, AKindThatExistsIsRefusedAndThePluginAddsNothing) {
  const std::string error = FactoryErrorOf(Config("[" + Quoted(TEST_PLUGIN_CLASH_PATH) + "]", "test_first"));
  EXPECT_NE(error.find("plugins[0]: " + std::string(TEST_PLUGIN_CLASH_PATH) +
                       ": controller kind 'go_to_goal' is already registered (built in)"),
            std::string::npos)
      << error;
  EXPECT_FALSE(Knows("test_first"));
}

TEST(ControllerPluginTest, TwoPluginsWithOneKindAreRefusedNamingTheFirst) {
  const std::string error =
      FactoryErrorOf(Config("[" + Quoted(TEST_PLUGIN_GOOD_PATH) + ", " + Quoted(TEST_PLUGIN_TWIN_PATH) + "]"));
  EXPECT_NE(error.find("plugins[1]: " + std::string(TEST_PLUGIN_TWIN_PATH) +
                       ": controller kind 'test_still' is already registered (" + TEST_PLUGIN_GOOD_PATH + ")"),
            std::string::npos)
      << error;
}

// A builder with every optional member ControllerKind::Of reads.
class FussyBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "fussy";
  static constexpr bool kGraphMustConnect = true;
  static std::vector<const char*> Keys() { return {"a", "b"}; }
  static kind_api::AgentPartsConfig DefaultParts(int num_robots) {
    kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::Defaults(num_robots);
    parts.robot.vel_gain = 0.5;
    return parts;
  }
  FussyBuilder(const config::ConfigNode&, int) {}
  std::unique_ptr<Robot> MakeRobot(int, const RobotParams&) const override { return nullptr; }
  std::unique_ptr<ExperimentMetrics> MakeMetrics() const override { return nullptr; }
};

TEST(ControllerKindTest, OfReadsTheBuildersStaticMembers) {
  const kind_api::ControllerKind kind = kind_api::ControllerKind::Of<FussyBuilder>();
  EXPECT_EQ(kind.name, "fussy");
  EXPECT_EQ(kind.keys, (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(kind.graph_must_connect);
  EXPECT_EQ(kind.default_parts(3).robot.vel_gain, 0.5);
  EXPECT_NE(kind.make_builder(config::ConfigNode(), 3), nullptr);
  // Without them: no graph requirement (the built-in go_to_goal).
  ASSERT_NE(agent_host::ControllerRegistry::BuiltIns().Find("go_to_goal"), nullptr);
  EXPECT_FALSE(agent_host::ControllerRegistry::BuiltIns().Find("go_to_goal")->graph_must_connect);
  EXPECT_TRUE(agent_host::ControllerRegistry::BuiltIns().Find("line_deployment")->graph_must_connect);
}

TEST(ControllerRegistryTest, RefusesNamelessKindsAndDuplicates) {
  agent_host::ControllerRegistry registry;
  EXPECT_THROW(registry.Add(kind_api::ControllerKind()), std::invalid_argument);
  registry.Add(kind_api::ControllerKind::Of<FussyBuilder>(), "here");
  try {
    registry.Add(kind_api::ControllerKind::Of<FussyBuilder>(), "there");
    ADD_FAILURE() << "a duplicate kind was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "controller kind 'fussy' is registered twice (here and there)");
  }
  EXPECT_EQ(registry.Names(), std::vector<std::string>{"fussy"});
  EXPECT_EQ(registry.Find("nothing"), nullptr);
}

}  // namespace
}  // namespace dream::agents
