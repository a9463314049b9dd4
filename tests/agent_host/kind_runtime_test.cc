// Issue 24: the python kind is a kind like the others. The tools ask a run's
// kind where its robots run, what spec its runtime gets and which file its
// run folder keeps (ControllerKind, through the registry), never its name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "../support/source_tree.h"

namespace dream::agent_host {
namespace {

using Runtime = kind_api::ControllerKind::Runtime;

run_config::RunConfig ShippedConfig(const std::string& name) {
  return run_config::LoadRunConfigFile(dream::testing::SourceDir() + "/config/" + name);
}

TEST(KindRuntimeTest, ThePythonKindRunsInThePythonRuntimeWithItsSpecAndModule) {
  const run_config::RunConfig config = ShippedConfig("go_to_goal_python.yaml");
  const std::shared_ptr<const kind_api::ControllerKind> kind = ControllerRegistry::KindOf(config);
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(kind->runtime, Runtime::kPython);
  EXPECT_EQ(kind->file_key, "module");
  ASSERT_TRUE(kind->runtime_spec);
  const nlohmann::json spec = nlohmann::json::parse(kind->runtime_spec(config));
  EXPECT_EQ(spec["format"], 1);
  EXPECT_EQ(spec["robots"], config.num_robots);
  EXPECT_THAT(spec["module"].get<std::string>(), ::testing::EndsWith("config/python/go_to_goal.py"));
  // The factory of the run says the same of its kind.
  EXPECT_EQ(ControllerFactory(config).registered_kind().runtime, Runtime::kPython);
}

TEST(KindRuntimeTest, EveryOtherBuiltInKindRunsItsCppRobotsAndKeepsNoFile) {
  int python_kinds = 0;
  for (const std::string& name : ControllerRegistry::BuiltIns().Names()) {
    SCOPED_TRACE(name);
    const kind_api::ControllerKind* kind = ControllerRegistry::BuiltIns().Find(name);
    if (kind->runtime == Runtime::kPython) {
      ++python_kinds;
      EXPECT_TRUE(kind->runtime_spec);
      continue;
    }
    EXPECT_FALSE(kind->runtime_spec);
    EXPECT_TRUE(kind->file_key.empty());
  }
  EXPECT_EQ(python_kinds, 1);
  EXPECT_EQ(ControllerFactory(ShippedConfig("go_to_goal.yaml")).registered_kind().runtime, Runtime::kCpp);
}

TEST(KindRuntimeTest, KindOfAConfigWithoutAKnownKindIsNone) {
  run_config::RunConfig config = ShippedConfig("go_to_goal.yaml");
  config.controller = config::ConfigNode::LoadString("kind: no_such_kind\n", "unknown.yaml");
  EXPECT_EQ(ControllerRegistry::KindOf(config), nullptr);
  config.controller = config::ConfigNode::LoadString("goals: []\n", "no_kind.yaml");
  EXPECT_EQ(ControllerRegistry::KindOf(config), nullptr);
}

TEST(KindRuntimeTest, TheBuiltInKindsAreThoseOfAgentsKindsInTheirOrder) {
  EXPECT_THAT(ControllerRegistry::BuiltIns().Names(),
              ::testing::ElementsAre("go_to_goal", "affine_formation", "voronoi_coverage", "hrvo_circle",
                                     "line_deployment", "calibration_drive", "python"));
}

}  // namespace
}  // namespace dream::agent_host
