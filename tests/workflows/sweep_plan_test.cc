#include "dream/workflows/sweep_plan.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "dream/config/config_node.h"
#include "dream/config_overrides/config_text.h"
#include "dream/run_config/run_config.h"

namespace dream::workflows {
namespace {

const char* kBase = R"(# a comment the generated config does not need
name: demo
seed: 1
robots: 2
initial_poses: {generate: {min_spacing_m: 0.3}}
controller:
  kind: go_to_goal
  max_speed_mps: 0.15
  goals: [[0.2, 0.2], [-0.2, -0.2]]
)";

TEST(SweepPlan, EveryCombinationForEverySeedParametersOuter) {
  const SweepPlan plan({3, 4}, {config_overrides::SweepParameter::Parse("controller.max_speed_mps=0.1,0.2"),
                                config_overrides::SweepParameter::Parse("controller.hrvo.variant=exact,thesis")});
  ASSERT_EQ(plan.runs().size(), 8u);
  EXPECT_EQ(plan.parameter_keys(), (std::vector<std::string>{"controller.max_speed_mps", "controller.hrvo.variant"}));
  const SweepPlan::Run& first = plan.runs()[0];
  EXPECT_EQ(first.seed, 3u);
  EXPECT_EQ(first.name, "seed3_max_speed_mps-0.1_variant-exact");
  EXPECT_EQ(first.Label(), "seed 3, max_speed_mps=0.1, variant=exact");
  EXPECT_EQ(plan.runs()[1].name, "seed4_max_speed_mps-0.1_variant-exact");
  EXPECT_EQ(plan.runs()[2].name, "seed3_max_speed_mps-0.1_variant-thesis");
  EXPECT_EQ(plan.runs()[7].name, "seed4_max_speed_mps-0.2_variant-thesis");
  std::set<std::string> names;
  for (size_t i = 0; i < plan.runs().size(); ++i) {
    EXPECT_EQ(plan.runs()[i].index, i);
    names.insert(plan.runs()[i].name);
  }
  EXPECT_EQ(names.size(), 8u);
}

TEST(SweepPlan, SeedsArePaddedSoFoldersSortAndNamesStaySafe) {
  const SweepPlan seeds({1, 20}, {});
  EXPECT_EQ(seeds.runs()[0].name, "seed01");
  EXPECT_EQ(seeds.runs()[1].name, "seed20");
  EXPECT_EQ(seeds.runs()[0].Label(), "seed 1");
  // Values with characters a folder name should not have; two that differ only there stay apart.
  const SweepPlan lists({1}, {config_overrides::SweepParameter::Parse("controller.goals.0=[0.1, 0.2],[0.1; 0.2]")});
  EXPECT_EQ(lists.runs()[0].name, "seed1_goals.0-0.1-0.2");
  EXPECT_EQ(lists.runs()[1].name, "seed1_goals.0-0.1-0.2_1");
}

TEST(SweepPlan, RefusesRepeatedKeysAndHugeSweeps) {
  EXPECT_THROW(SweepPlan({1}, {config_overrides::SweepParameter::Parse("steps=1,2"),
                               config_overrides::SweepParameter::Parse("steps=3")}),
               std::invalid_argument);
  EXPECT_THROW(SweepPlan({}, {}), std::invalid_argument);
  std::vector<uint64_t> many(1000);
  for (size_t i = 0; i < many.size(); ++i) many[i] = i;
  std::string values = "1";
  for (int i = 2; i <= 101; ++i) values += "," + std::to_string(i);
  EXPECT_THROW(SweepPlan(many, {config_overrides::SweepParameter::Parse("steps=" + values)}), std::invalid_argument);
}

// --zip: keys varied together (a controller's range with its sensor's), the
// i-th values in one run, in every combination with the --set keys.
TEST(SweepPlan, ZippedKeysVaryTogetherInEveryCombinationWithTheSetKeys) {
  using config_overrides::SweepParameter;
  const SweepPlan plan({1, 2}, {SweepParameter::Parse("controller.hrvo.variant=exact,thesis")},
                       {SweepParameter::Parse("controller.max_speed_mps=0.1,0.2,0.3"),
                        SweepParameter::Parse("controller.sensors.0.range_m=0.5,1.0,1.5")});
  ASSERT_EQ(plan.runs().size(), 2u * 2u * 3u);
  EXPECT_EQ(plan.parameter_keys(), (std::vector<std::string>{"controller.hrvo.variant", "controller.max_speed_mps",
                                                             "controller.sensors.0.range_m"}));
  std::set<std::pair<std::string, std::string>> speed_with_range;
  for (const SweepPlan::Run& run : plan.runs()) {
    ASSERT_EQ(run.parameters.size(), 3u);
    speed_with_range.insert({run.parameters[1].second, run.parameters[2].second});
  }
  EXPECT_EQ(speed_with_range,
            (std::set<std::pair<std::string, std::string>>{{"0.1", "0.5"}, {"0.2", "1.0"}, {"0.3", "1.5"}}));
  EXPECT_EQ(plan.runs()[0].name, "seed1_variant-exact_max_speed_mps-0.1_range_m-0.5");
  EXPECT_EQ(plan.runs()[2].name, "seed1_variant-exact_max_speed_mps-0.2_range_m-1.0");
  EXPECT_EQ(plan.runs()[2].Label(), "seed 1, variant=exact, max_speed_mps=0.2, range_m=1.0");
}

TEST(SweepPlan, ZippedKeysNeedAsManyValuesAndNoKeyIsSweptTwice) {
  using config_overrides::SweepParameter;
  try {
    SweepPlan({1}, {},
              {SweepParameter::Parse("controller.max_speed_mps=0.1,0.2"), SweepParameter::Parse("steps=10,20,30")});
    FAIL() << "zipped keys with 2 and 3 values were planned";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--zip steps has 3 values and --zip controller.max_speed_mps 2"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(SweepPlan({1}, {SweepParameter::Parse("steps=1,2")}, {SweepParameter::Parse("steps=3,4")}),
               std::invalid_argument);
}

TEST(SweepPlan, RunConfigHasSeedNameAndParametersAndPassesTheConfigCheck) {
  const SweepPlan plan({7}, {config_overrides::SweepParameter::Parse("controller.max_speed_mps=0.1"),
                             config_overrides::SweepParameter::Parse("steps=250")});
  const SweepPlan::Run& run = plan.runs()[0];
  const YAML::Node config = SweepPlan::MakeRunConfig(kBase, "base.yaml", run);
  const std::string text = config_overrides::ConfigText(config, "generated for a test\nsecond line");
  EXPECT_EQ(text.rfind("# generated for a test\n# second line\n", 0), 0u) << text;
  const run_config::RunConfig loaded = run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "run.yaml"));
  EXPECT_EQ(loaded.seed, 7u);
  EXPECT_EQ(loaded.name, "demo_" + run.name);
  EXPECT_EQ(loaded.sim.max_steps, 250);
  EXPECT_EQ(loaded.controller.Required("max_speed_mps").AsDouble(), 0.1);
  // The seed drives the generated start poses: another seed, other poses.
  const SweepPlan other({8}, {});
  const run_config::RunConfig eight = run_config::LoadRunConfig(config::ConfigNode::LoadString(
      config_overrides::ConfigText(SweepPlan::MakeRunConfig(kBase, "base.yaml", other.runs()[0]), ""), "run8.yaml"));
  EXPECT_NE(eight.initial_poses[0].x_m, loaded.initial_poses[0].x_m);
}

TEST(SweepPlan, EachRunConfigStartsFromTheBaseText) {
  const SweepPlan plan({1}, {config_overrides::SweepParameter::Parse("controller.max_speed_mps=0.05,0.2")});
  const YAML::Node a = SweepPlan::MakeRunConfig(kBase, "base.yaml", plan.runs()[0]);
  const YAML::Node b = SweepPlan::MakeRunConfig(kBase, "base.yaml", plan.runs()[1]);
  EXPECT_EQ(a["controller"]["max_speed_mps"].as<double>(), 0.05);
  EXPECT_EQ(b["controller"]["max_speed_mps"].as<double>(), 0.2);
  EXPECT_EQ(a["name"].as<std::string>(), "demo_seed1_max_speed_mps-0.05");
}

TEST(SweepPlan, RelativePluginPathsKeepPointingAtTheBaseConfigsFolder) {
  const SweepPlan plan({1}, {});
  const YAML::Node config =
      SweepPlan::MakeRunConfig(std::string(kBase) + "plugins: [libmine.so]\n", "/some/where/base.yaml", plan.runs()[0]);
  EXPECT_EQ(config["plugin_dir"].as<std::string>(), "/some/where");
  const YAML::Node plain = SweepPlan::MakeRunConfig(kBase, "/some/where/base.yaml", plan.runs()[0]);
  EXPECT_FALSE(plain["plugin_dir"].IsDefined());
}

TEST(SweepPlan, ABaseThatIsNotAMappingIsAnError) {
  const SweepPlan plan({1}, {});
  EXPECT_THROW(SweepPlan::MakeRunConfig("- 1\n- 2\n", "base.yaml", plan.runs()[0]), std::invalid_argument);
  EXPECT_THROW(SweepPlan::MakeRunConfig("a: [1\n", "base.yaml", plan.runs()[0]), std::invalid_argument);
}

}  // namespace
}  // namespace dream::workflows
