// The one-class controller that docs/writing-a-controller.md leads with
// (docs/examples/out_of_tree_controller/orbit_controller.cc, built by CMake
// as a plugin from that very file), with the example's own orbit.yaml: the
// document shows the file verbatim, the plugin loads, the robots circle as
// the code says, and the kind's keys and values are checked like a shipped
// kind's.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/config/config_error.h"
#include "dream/run_config/run_config.h"
#include "dream/files/file_text.h"
#include "../support/factory_error.h"
#include "scenario_runner.h"
#include "../support/source_tree.h"

namespace dream::agents {
namespace {

const std::string kExampleDir = dream::testing::SourceDir() + "/docs/examples/out_of_tree_controller";

/// Replaces the one occurrence of `from` in `text` by `to`.
std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The example's orbit.yaml, naming the plugin this build made, with
/// `from` replaced by `to`; errors name orbit.yaml.
run_config::RunConfig ExampleConfig(const std::string& from = "", const std::string& to = "") {
  std::string text = Replaced(files::ReadFileText(kExampleDir + "/orbit.yaml"), "build/liborbit_controller.so",
                              std::string("'") + ORBIT_EXAMPLE_PLUGIN_PATH + "'");
  if (!from.empty()) text = Replaced(text, from, to);
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "orbit.yaml"));
}

/// The 1-based line of orbit.yaml that starts with `start`.
int LineOf(const std::string& start) {
  std::istringstream text(files::ReadFileText(kExampleDir + "/orbit.yaml"));
  std::string line;
  for (int number = 1; std::getline(text, line); ++number) {
    if (line.rfind(start, 0) == 0) return number;
  }
  ADD_FAILURE() << "orbit.yaml has no line starting with " << start;
  return 0;
}

using testing::FactoryErrorOf;

TEST(OrbitExampleTest, TheDocumentLeadsWithTheExampleFileVerbatim) {
  const std::string document = files::ReadFileText(dream::testing::SourceDir() + "/docs/writing-a-controller.md");
  const std::string fence = "```cpp\n";
  const size_t start = document.find(fence);
  ASSERT_NE(start, std::string::npos) << "no ```cpp block in docs/writing-a-controller.md";
  const size_t code = start + fence.size();
  const size_t end = document.find("```", code);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(document.substr(code, end - code), files::ReadFileText(kExampleDir + "/orbit_controller.cc"))
      << "the first C++ block of docs/writing-a-controller.md must be orbit_controller.cc as it is";
}

TEST(OrbitExampleTest, ThePluginLoadsAndTheRobotsCircleTheirStartingCircles) {
  const run_config::RunConfig config = ExampleConfig();
  const agent_host::ControllerFactory factory(config);  // loads the plugin
  EXPECT_EQ(factory.kind(), "orbit");
  EXPECT_EQ(factory.MakeMetrics().size(), 1u) << "one class: only the safety metrics";

  const scenario::ScenarioResult run = scenario::RunScenario(config, "orbit_example");
  ASSERT_TRUE(run.outcome.ok()) << run.outcome.reason;
  EXPECT_EQ(run.violations, world::ViolationCounts()) << "the verdict is clean, actuators included";
  EXPECT_GT(scenario::Value(run, "min_pairwise_distance_m"), 0.25);
  const double radius_m = config.controller.Required("radius_m").AsDouble();
  const double speed_mps = config.controller.Required("speed_mps").AsDouble();
  const double run_s = static_cast<double>(config.sim.max_steps) * config.world.time_step_s;
  for (size_t id = 0; id < run.final_poses.size(); ++id) {
    const world::Pose2& start = config.initial_poses[id];
    const world::Pose2& end = run.final_poses[id];
    // The circle is radius_m to the left of the start pose.
    const double center_x_m = start.x_m - radius_m * std::sin(start.theta_rad);
    const double center_y_m = start.y_m + radius_m * std::cos(start.theta_rad);
    // (The unicycle tracks a point ahead of it, so it runs a little wide.)
    EXPECT_NEAR(std::hypot(end.x_m - center_x_m, end.y_m - center_y_m), radius_m, 0.02) << "robot " << id;
    // Counter-clockwise at about speed_mps (a few percent behind: it starts
    // from rest): the angle around the centre it ends at. Standing still or
    // turning the other way would be more than a radian off.
    const double start_angle_rad = std::atan2(start.y_m - center_y_m, start.x_m - center_x_m);
    const double end_angle_rad = std::atan2(end.y_m - center_y_m, end.x_m - center_x_m);
    const double expected_rad = start_angle_rad + speed_mps * run_s / radius_m;
    EXPECT_NEAR(std::remainder(end_angle_rad - expected_rad, 2.0 * M_PI), 0.0, 0.5) << "robot " << id;
  }
}

TEST(OrbitExampleTest, AnUnknownKeyNamesFileLineAndTheAllowedKeys) {
  const std::string error = FactoryErrorOf(ExampleConfig("  radius_m:", "  radius:"));
  EXPECT_EQ(error, "orbit.yaml:" + std::to_string(LineOf("  radius_m:")) +
                       ": controller.radius: unknown key for kind orbit "
                       "(did you mean 'radius_m'?); allowed keys here: kind, robot, sensors, "
                       "radio, radius_m, speed_mps");
}

TEST(OrbitExampleTest, ABadValueNamesFileLineAndKey) {
  const std::string error = FactoryErrorOf(ExampleConfig("speed_mps: 0.1", "speed_mps: -0.1"));
  EXPECT_EQ(error, "orbit.yaml:" + std::to_string(LineOf("  speed_mps:")) + ": controller.speed_mps: must be > 0");
  const std::string text = FactoryErrorOf(ExampleConfig("radius_m: 0.25", "radius_m: big"));
  EXPECT_EQ(
      text.rfind(
          "orbit.yaml:" + std::to_string(LineOf("  radius_m:")) + ": controller.radius_m: expected a number, got", 0),
      0u)
      << text;
}

}  // namespace
}  // namespace dream::agents
