#include "dream/config_overrides/config_override.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "dream/config_overrides/sweep_parameter.h"

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
    config_overrides::ApplyConfigOverride(root, key, value, "demo.yaml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ConfigOverride, SetsNestedKeysAndListItems) {
  YAML::Node root = YAML::Load(kConfig);
  config_overrides::ApplyConfigOverride(root, "controller.max_speed_mps", "0.1", "demo.yaml");
  config_overrides::ApplyConfigOverride(root, "controller.sensors.0.period_steps", "3", "demo.yaml");
  config_overrides::ApplyConfigOverride(root, "controller.goals.1", "[0.3, -0.3]", "demo.yaml");
  config_overrides::ApplyConfigOverride(root, "robots", "2", "demo.yaml");
  EXPECT_EQ(root["controller"]["max_speed_mps"].as<double>(), 0.1);
  EXPECT_EQ(root["controller"]["sensors"][0]["period_steps"].as<int>(), 3);
  EXPECT_EQ(root["controller"]["goals"][1][0].as<double>(), 0.3);
  EXPECT_EQ(root["controller"]["goals"][1][1].as<double>(), -0.3);
  EXPECT_EQ(root["controller"]["goals"][0][0].as<double>(), 0.2);  // neighbours untouched
  EXPECT_EQ(root["controller"]["kind"].as<std::string>(), "go_to_goal");
}

TEST(ConfigOverride, AddsALastKeyTheConfigLeavesOut) {
  YAML::Node root = YAML::Load(kConfig);
  config_overrides::ApplyConfigOverride(root, "controller.sensors.0.noise_std", "0.002", "demo.yaml");
  EXPECT_EQ(root["controller"]["sensors"][0]["noise_std"].as<double>(), 0.002);
  // The config check then accepts it as a key it knows.
  EXPECT_NO_THROW(run_config::LoadRunConfig(config::ConfigNode(root, "demo.yaml", "")));
}

TEST(ConfigOverride, CreatesASectionTheSchemaKnowsWhenTheConfigLeavesItOut) {
  YAML::Node root = YAML::Load(kConfig);  // no world: section
  config_overrides::ApplyConfigOverride(root, "world.realism", "lab", "demo.yaml");
  config_overrides::ApplyConfigOverride(root, "world.agent_timeout_s", "1", "demo.yaml");
  EXPECT_EQ(root["world"]["realism"].as<std::string>(), "lab");
  EXPECT_EQ(root["world"]["agent_timeout_s"].as<double>(), 1.0);
  const run_config::RunConfig config = run_config::LoadRunConfig(config::ConfigNode(root, "demo.yaml", ""));
  EXPECT_FALSE(config.realism.IsIdeal());

  YAML::Node nested = YAML::Load(kConfig);  // two sections created at once
  config_overrides::ApplyConfigOverride(nested, "world.realism.preset", "lab", "demo.yaml");
  EXPECT_EQ(nested["world"]["realism"]["preset"].as<std::string>(), "lab");
  EXPECT_NO_THROW(run_config::LoadRunConfig(config::ConfigNode(nested, "demo.yaml", "")));

  YAML::Node guarded = YAML::Load(kConfig);  // no barriers: section
  config_overrides::ApplyConfigOverride(guarded, "barriers.kind", "unicycle", "demo.yaml");
  EXPECT_TRUE(run_config::LoadRunConfig(config::ConfigNode(guarded, "demo.yaml", "")).barriers.InWorld());
}

TEST(ConfigOverride, UnknownKeysAndIndicesAreErrorsNamingThem) {
  EXPECT_EQ(ErrorOf("controller.robot.max_speed_mps", "0.1"),
            "--set controller.robot.max_speed_mps: demo.yaml has no key 'robot' under controller "
            "(keys there: kind, max_speed_mps, goals, sensors)");
  EXPECT_EQ(ErrorOf("contoller.max_speed_mps", "0.1"),
            "--set contoller.max_speed_mps: demo.yaml has no key 'contoller' at the top level "
            "(did you mean 'controller'?) (keys there: name, seed, robots, initial_poses, controller)");
  EXPECT_EQ(ErrorOf("wrold.realism", "lab"),
            "--set wrold.realism: demo.yaml has no key 'wrold' at the top level "
            "(did you mean 'world'?) (keys there: name, seed, robots, initial_poses, controller)");
  EXPECT_EQ(ErrorOf("controller.sensors.3.noise_std", "0.1"),
            "--set controller.sensors.3.noise_std: controller.sensors has 1 items in demo.yaml, no index 3");
  EXPECT_EQ(ErrorOf("controller.sensors.first.noise_std", "0.1"),
            "--set controller.sensors.first.noise_std: controller.sensors is a list in demo.yaml; the next part "
            "must be an index 0..0, got 'first'");
  EXPECT_EQ(ErrorOf("controller.kind.x", "1"),
            "--set controller.kind.x: controller.kind is a single value in demo.yaml, it has no 'x'");
  EXPECT_NE(ErrorOf("controller.max_speed_mps", "[0.1").find("is not valid YAML"), std::string::npos);
}

/// A flow list holding anchors a0..a<levels-1>, each ten aliases of the one
/// before (a0 ten x's), then `extra` more aliases of the last: values that
/// double as a "billion laughs" when `levels` is large.
std::string Laughs(int levels, int extra) {
  std::string text = "[&a0 [x, x, x, x, x, x, x, x, x, x]";
  for (int i = 1; i < levels; ++i) {
    text += ", &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) text += (k ? ", *a" : "*a") + std::to_string(i - 1);
    text += "]";
  }
  for (int k = 0; k < extra; ++k) text += ", *a" + std::to_string(levels - 1);
  return text + "]";
}

TEST(ConfigOverride, AValueHasTheLimitsOfAConfigFile) {
  // Before: copying a value that contains itself overflowed the stack (SIGSEGV).
  EXPECT_EQ(ErrorOf("controller.goals", "&a [*a]"),
            "--set controller.goals:1: [0]: contains itself through an alias (*); write the value out instead");
  // Before: a 300-byte value took 36 s and 3.9 GB, then std::bad_alloc.
  const std::string laughs = ErrorOf("controller.goals", Laughs(10, 0));
  EXPECT_NE(laughs.find("--set controller.goals:1: "), std::string::npos) << laughs;
  EXPECT_NE(laughs.find("aliases (*) expand this value to more than 1000000 values"), std::string::npos) << laughs;
  // Nesting counts from the top of the config: 2 levels of key and 101 of value.
  const std::string deep = std::string(101, '[') + std::string(101, ']');
  EXPECT_EQ(ErrorOf("controller.goals", deep),
            "--set controller.goals: the value would nest the config 102 levels deep; at most 100");
  EXPECT_EQ(ErrorOf("controller.goals", std::string(98, '[') + std::string(98, ']')), "(no error)");
  EXPECT_EQ(ErrorOf("controller.goals", "{a: 1, a: 2}"),
            "--set controller.goals:1: a: duplicate key; first given at line 1");
  EXPECT_NE(ErrorOf("name", std::string(config::ConfigNode::kMaxFileBytes + 1, 'x')).find("at most 16777216"),
            std::string::npos);
}

TEST(ConfigOverride, TheConfigWithTheValueStaysWithinAConfigFilesLimit) {
  // The file's aliases expand to 969,133 values (a file may: up to 1,000,000).
  YAML::Node root = YAML::Load(std::string(kConfig) + "big: " + Laughs(5, 7) + "\nbig2: " + Laughs(4, 5) + "\n");
  config_overrides::ApplyConfigOverride(root, "controller.a", Laughs(3, 0), "demo.yaml");  // 1,234 more: allowed
  EXPECT_EQ(root["controller"]["a"].size(), 3u);
  try {
    config_overrides::ApplyConfigOverride(root, "controller.b", Laughs(4, 7), "demo.yaml");  // 90,122 more: not
    FAIL() << "a config past 1,000,000 values was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--set controller.b: the config ("), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("and this value (90122 values once its aliases are expanded) exceed "
                                         "1000000 values"),
              std::string::npos)
        << e.what();
  }
}

TEST(ConfigOverride, AValueIsCopiedSoItsExpansionIsBounded) {
  // 101,233 values once expanded, from 300 bytes: a file may hold that (it
  // shares the nodes), a --set value is copied (it took 2.8 s and 440 MB at
  // 900,000 values; found by fuzzing).
  EXPECT_EQ(ErrorOf("controller.goals", Laughs(4, 8)),
            "--set controller.goals: the value holds 101233 values once its aliases are expanded; a --set value may "
            "hold at most 100000 (it is copied into the config; put a larger value in the config file)");
  EXPECT_EQ(ErrorOf("controller.goals", Laughs(4, 7)), "(no error)");  // 90,122
}

TEST(ConfigOverride, AMisspeltNewLastKeyIsCaughtByTheConfigCheck) {
  // (The controller section's keys are checked by the agents' factory, which
  // the integration test exercises; the top level by LoadRunConfig.)
  YAML::Node top = YAML::Load(kConfig);
  config_overrides::ApplyConfigOverride(top, "stepz", "10", "demo.yaml");
  try {
    run_config::LoadRunConfig(config::ConfigNode(top, "demo.yaml", ""));
    FAIL() << "an unknown top-level key passed the config check";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("stepz: unknown key"), std::string::npos) << e.what();
  }
}

TEST(ConfigOverride, AnErrorAboutAnOverriddenValuePointsAtItsLineInTheBaseFile) {
  YAML::Node root = YAML::Load(kConfig);
  config_overrides::ApplyConfigOverride(root, "robots", "0", "demo.yaml");
  try {
    run_config::LoadRunConfig(config::ConfigNode(root, "demo.yaml", ""));
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
  config_overrides::ApplyConfigOverride(root, "controller.sensors.0.kind", "odometry", "demo.yaml");
  EXPECT_TRUE(root["controller"].IsMap());
  EXPECT_EQ(root["controller"]["goals"].size(), 2u);
  EXPECT_EQ(root["name"].as<std::string>(), "demo");
}

TEST(SweepParameter, ParsesKeyAndValuesSplittingOnlyTopLevelCommas) {
  const config_overrides::SweepParameter speeds =
      config_overrides::SweepParameter::Parse("controller.max_speed_mps=0.1, 0.15,0.2");
  EXPECT_EQ(speeds.key, "controller.max_speed_mps");
  EXPECT_EQ(speeds.values, (std::vector<std::string>{"0.1", "0.15", "0.2"}));
  EXPECT_EQ(speeds.ShortName(), "max_speed_mps");
  const config_overrides::SweepParameter goals =
      config_overrides::SweepParameter::Parse("controller.goals.0=[0.1, 0.2],[0.3,0.4],'a,b'");
  EXPECT_EQ(goals.values, (std::vector<std::string>{"[0.1, 0.2]", "[0.3,0.4]", "'a,b'"}));
  EXPECT_EQ(goals.ShortName(), "goals.0");
  EXPECT_EQ(config_overrides::SweepParameter::Parse("steps=100").ShortName(), "steps");
}

TEST(SweepParameter, BadTextIsAnErrorNamingTheOption) {
  auto error_of = [](const std::string& text) -> std::string {
    try {
      config_overrides::SweepParameter::Parse(text);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_NE(error_of("controller.max_speed_mps").find("expected KEY=V1,V2"), std::string::npos);
  EXPECT_NE(error_of("=1,2").find("the key before '=' is empty"), std::string::npos);
  EXPECT_NE(error_of("a..b=1").find("is not a dotted key"), std::string::npos);
  // A control byte (or NUL, through the library) in a key would make the run folder's config.yaml
  // unreadable (found by fuzzing); the message shows it escaped.
  EXPECT_EQ(
      error_of("controller.max\x01r=4"),
      "--set controller.max\\x01r=4: 'controller.max\\x01r' is not a dotted key like controller.sensors.0.noise_std");
  EXPECT_NE(error_of(std::string("controller.max\0r=4", 18)).find("'controller.max\\x00r' is not a dotted key"),
            std::string::npos);
  EXPECT_NE(error_of("controller.m\xa1x=4").find("is not a dotted key"), std::string::npos);
  EXPECT_NE(error_of("a.b=1,,2").find("empty value"), std::string::npos);
  EXPECT_NE(error_of("a.b=").find("empty value"), std::string::npos);
  EXPECT_NE(error_of("a.b=[1,2").find("unclosed"), std::string::npos);
  EXPECT_NE(error_of("seed=1,2").find("--seeds"), std::string::npos);
  EXPECT_EQ(error_of("a.b=1").find("(no error)"), 0u);
}

}  // namespace
}  // namespace dream::cli
