// The HRVO one-class example of docs/writing-a-controller.md
// (docs/examples/out_of_tree_controller/swap_controller.cc, built by CMake as
// a plugin from that very file), with the example's own swap.yaml: the
// document shows the file verbatim, the plugin loads, every robot reaches the
// point opposite its start, nobody collides (HRVO at work: all six cross the
// centre), and done() ends the run before its step limit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/run_config/run_config.h"
#include "dream/files/file_text.h"
#include "scenario_runner.h"
#include "../support/source_tree.h"

namespace dream::agents {
namespace {

const std::string kExampleDir = dream::testing::SourceDir() + "/docs/examples/out_of_tree_controller";

run_config::RunConfig ExampleConfig() {
  std::string text = files::ReadFileText(kExampleDir + "/swap.yaml");
  const std::string plugin = "build/libswap_controller.so";
  const size_t at = text.find(plugin);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.replace(at, plugin.size(), std::string("'") + SWAP_EXAMPLE_PLUGIN_PATH + "'");
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "swap.yaml"));
}

TEST(SwapExampleTest, TheDocumentShowsTheExampleFileVerbatim) {
  const std::string document = files::ReadFileText(dream::testing::SourceDir() + "/docs/writing-a-controller.md");
  const std::string file = files::ReadFileText(kExampleDir + "/swap_controller.cc");
  EXPECT_NE(document.find("```cpp\n" + file + "```"), std::string::npos)
      << "docs/writing-a-controller.md must show swap_controller.cc as it is, in a ```cpp block";
}

TEST(SwapExampleTest, EveryRobotReachesTheOppositePointWithoutACollisionAndTheRunEndsWhenAllAreDone) {
  const run_config::RunConfig config = ExampleConfig();
  EXPECT_EQ(agent_host::ControllerFactory(config).kind(), "swap");
  const scenario::ScenarioResult run = scenario::RunScenario(config, "swap_example");
  ASSERT_TRUE(run.outcome.ok()) << run.outcome.reason;
  EXPECT_EQ(run.violations.collision_errors, 0);
  EXPECT_EQ(run.violations.boundary_errors, 0);
  EXPECT_EQ(run.outcome.robots_done.size(), config.initial_poses.size());
  EXPECT_LT(run.outcome.steps, config.sim.max_steps) << "done() should end the run early";
  const double tolerance_m = config.controller.Required("tolerance_m").AsDouble();
  for (size_t id = 0; id < run.final_poses.size(); ++id) {
    const world::Pose2& start = config.initial_poses[id];
    const world::Pose2& end = run.final_poses[id];
    // Stopped within the tolerance (and the few mm a last step carries it).
    EXPECT_LT(std::hypot(end.x_m + start.x_m, end.y_m + start.y_m), tolerance_m + 0.01) << "robot " << id;
  }
}

}  // namespace
}  // namespace dream::agents
