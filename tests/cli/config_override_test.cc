#include "config_override.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "dream/config/config_node.h"
#include "dream/config/run_config.h"
#include "sweep_parameter.h"

namespace dream::cli {
namespace {

const char* kConfig = R"(name: demo
seed: 1
robots: 2
initial_poses:
  - [0.5, 0.0, 0.0]
  - [-0.5, 0.0, 3.14]
controller:
  kind: go_to_goal
  max_speed_mps: 0.15
  goals: [[0.2, 0.2], [-0.2, -0.2]]
  sensors:
    - {kind: odometry, period_steps: 2}
)";

std::string ErrorOf(const std::string& key, const std::string& value) {
  YAML::Node root = YAML::Load(kConfig);
  try {
    ApplyConfigOverride(root, key, value, "demo.yaml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ConfigOverride, SetsNestedKeysAndListItems) {
  YAML::Node root = YAML::Load(kConfig);
  ApplyConfigOverride(root, "controller.max_speed_mps", "0.1", "demo.yaml");
  ApplyConfigOverride(root, "controller.sensors.0.period_steps", "3", "demo.yaml");
  ApplyConfigOverride(root, "controller.goals.1", "[0.3, -0.3]", "demo.yaml");
  ApplyConfigOverride(root, "robots", "2", "demo.yaml");
  EXPECT_EQ(root["controller"]["max_speed_mps"].as<double>(), 0.1);
  EXPECT_EQ(root["controller"]["sensors"][0]["period_steps"].as<int>(), 3);
  EXPECT_EQ(root["controller"]["goals"][1][0].as<double>(), 0.3);
  EXPECT_EQ(root["controller"]["goals"][1][1].as<double>(), -0.3);
  EXPECT_EQ(root["controller"]["goals"][0][0].as<double>(), 0.2);  // neighbours untouched
  EXPECT_EQ(root["controller"]["kind"].as<std::string>(), "go_to_goal");
}

TEST(ConfigOverride, AddsALastKeyTheConfigLeavesOut) {
  YAML::Node root = YAML::Load(kConfig);
  ApplyConfigOverride(root, "controller.sensors.0.noise_std", "0.002", "demo.yaml");
  EXPECT_EQ(root["controller"]["sensors"][0]["noise_std"].as<double>(), 0.002);
  // The config check then accepts it as a key it knows.
  EXPECT_NO_THROW(config::LoadRunConfig(config::ConfigNode(root, "demo.yaml", "")));
}

TEST(ConfigOverride, UnknownKeysAndIndicesAreErrorsNamingThem) {
  EXPECT_EQ(ErrorOf("controller.robot.max_speed_mps", "0.1"),
            "--set controller.robot.max_speed_mps: demo.yaml has no key 'robot' under controller "
            "(keys there: kind, max_speed_mps, goals, sensors)");
  EXPECT_EQ(ErrorOf("contoller.max_speed_mps", "0.1"),
            "--set contoller.max_speed_mps: demo.yaml has no key 'contoller' at the top level "
            "(keys there: name, seed, robots, initial_poses, controller)");
  EXPECT_EQ(ErrorOf("controller.sensors.3.noise_std", "0.1"),
            "--set controller.sensors.3.noise_std: controller.sensors has 1 items in demo.yaml, no index 3");
  EXPECT_EQ(ErrorOf("controller.sensors.first.noise_std", "0.1"),
            "--set controller.sensors.first.noise_std: controller.sensors is a list in demo.yaml; the next part "
            "must be an index 0..0, got 'first'");
  EXPECT_EQ(ErrorOf("controller.kind.x", "1"),
            "--set controller.kind.x: controller.kind is a single value in demo.yaml, it has no 'x'");
  EXPECT_NE(ErrorOf("controller.max_speed_mps", "[0.1").find("is not valid YAML"), std::string::npos);
}

TEST(ConfigOverride, AMisspeltNewLastKeyIsCaughtByTheConfigCheck) {
  // (The controller section's keys are checked by the agents' factory, which
  // the integration test exercises; the top level by LoadRunConfig.)
  YAML::Node top = YAML::Load(kConfig);
  ApplyConfigOverride(top, "stepz", "10", "demo.yaml");
  try {
    config::LoadRunConfig(config::ConfigNode(top, "demo.yaml", ""));
    FAIL() << "an unknown top-level key passed the config check";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("stepz: unknown key"), std::string::npos) << e.what();
  }
}

TEST(ConfigOverride, AnErrorAboutAnOverriddenValuePointsAtItsLineInTheBaseFile) {
  YAML::Node root = YAML::Load(kConfig);
  ApplyConfigOverride(root, "robots", "0", "demo.yaml");
  try {
    config::LoadRunConfig(config::ConfigNode(root, "demo.yaml", ""));
    FAIL() << "robots: 0 passed the config check";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("demo.yaml:3: robots: must be between 1 and", 0), 0u) << e.what();
  }
}

TEST(ConfigOverride, OverridingDoesNotEditOtherNodes) {
  // yaml-cpp's Node::operator= overwrites what a node points at; walking the
  // key must rebind instead, or "controller.sensors.0" would overwrite
  // controller with its own sensor list.
  YAML::Node root = YAML::Load(kConfig);
  ApplyConfigOverride(root, "controller.sensors.0.kind", "odometry", "demo.yaml");
  EXPECT_TRUE(root["controller"].IsMap());
  EXPECT_EQ(root["controller"]["goals"].size(), 2u);
  EXPECT_EQ(root["name"].as<std::string>(), "demo");
}

TEST(SweepParameter, ParsesKeyAndValuesSplittingOnlyTopLevelCommas) {
  const SweepParameter speeds = SweepParameter::Parse("controller.max_speed_mps=0.1, 0.15,0.2");
  EXPECT_EQ(speeds.key, "controller.max_speed_mps");
  EXPECT_EQ(speeds.values, (std::vector<std::string>{"0.1", "0.15", "0.2"}));
  EXPECT_EQ(speeds.ShortName(), "max_speed_mps");
  const SweepParameter goals = SweepParameter::Parse("controller.goals.0=[0.1, 0.2],[0.3,0.4],'a,b'");
  EXPECT_EQ(goals.values, (std::vector<std::string>{"[0.1, 0.2]", "[0.3,0.4]", "'a,b'"}));
  EXPECT_EQ(goals.ShortName(), "goals.0");
  EXPECT_EQ(SweepParameter::Parse("steps=100").ShortName(), "steps");
}

TEST(SweepParameter, BadTextIsAnErrorNamingTheOption) {
  auto error_of = [](const std::string& text) -> std::string {
    try {
      SweepParameter::Parse(text);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_NE(error_of("controller.max_speed_mps").find("expected KEY=V1,V2"), std::string::npos);
  EXPECT_NE(error_of("=1,2").find("the key before '=' is empty"), std::string::npos);
  EXPECT_NE(error_of("a..b=1").find("is not a dotted key"), std::string::npos);
  EXPECT_NE(error_of("a.b=1,,2").find("empty value"), std::string::npos);
  EXPECT_NE(error_of("a.b=").find("empty value"), std::string::npos);
  EXPECT_NE(error_of("a.b=[1,2").find("unclosed"), std::string::npos);
  EXPECT_NE(error_of("seed=1,2").find("--seeds"), std::string::npos);
  EXPECT_EQ(error_of("a.b=1").find("(no error)"), 0u);
}

}  // namespace
}  // namespace dream::cli
