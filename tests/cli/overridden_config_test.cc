#include "dream/config_overrides/overridden_config.h"

#include "dream/run_config/run_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "../support/scratch_folder.h"

namespace dream::cli {
namespace {

const char* kConfig = R"(name: demo   # a comment the unchanged copy keeps
seed: 1
robots: 3
initial_poses: {generate: {min_spacing_m: 0.3}}
controller:
  kind: go_to_goal
  max_speed_mps: 0.15
  goals: [[0.2, 0.2], [-0.2, -0.2], [0.0, 0.5]]
)";

class OverriddenConfigTest : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(path_) << kConfig; }

  std::string ErrorOf(long long seed, const std::vector<std::string>& sets) const {
    try {
      config_overrides::OverriddenConfig(path_, seed, sets).LoadWith(&run_config::LoadRunConfig);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(no error)";
  }

  dream::testing::ScratchFolder folder_{"dream_overridden_config"};
  const std::filesystem::path dir_ = folder_.path();
  const std::string path_ = (dir_ / "demo.yaml").string();
};

// An earlier --set can change what a later one walks through: the error says
// so instead of blaming the file.
TEST_F(OverriddenConfigTest, AKeyAnEarlierSetMadeASingleValueIsNamedAsItsDoing) {
  EXPECT_EQ(ErrorOf(-1, {"controller.goals=none", "controller.goals.x=1"}),
            "--set controller.goals.x: controller.goals is a single value in " + path_ +
                " after --set controller.goals=none, it has no 'x'");
}

TEST_F(OverriddenConfigTest, WithoutOverridesTheFileIsReadAndCopiedAsItIs) {
  const config_overrides::OverriddenConfig overridden(path_, -1, {});
  const run_config::RunConfig config = overridden.LoadWith(&run_config::LoadRunConfig);
  EXPECT_EQ(config.seed, 1u);
  EXPECT_EQ(run_config::RunFolderConfigText(config, overridden.Text()), kConfig);  // comments kept
  EXPECT_EQ(overridden.OptionsText(), "");
}

TEST_F(OverriddenConfigTest, SeedAndSetsChangeTheRunAndTheFolderTextReloadsToTheSameRun) {
  const config_overrides::OverriddenConfig overridden(
      path_, 7, {"controller.max_speed_mps=0.1", "controller.goals.2=[0.4, 0.4]"});
  const run_config::RunConfig config = overridden.LoadWith(&run_config::LoadRunConfig);
  EXPECT_EQ(config.seed, 7u);
  EXPECT_EQ(overridden.OptionsText(),
            "--seed 7 --set controller.max_speed_mps=0.1 --set controller.goals.2=[0.4, 0.4]");
  EXPECT_NE(config.initial_poses[0].x_m, run_config::LoadRunConfigFile(path_).initial_poses[0].x_m)
      << "another seed must generate other start poses";

  const std::string text = run_config::RunFolderConfigText(config, overridden.Text());
  EXPECT_EQ(text.rfind("# " + path_ + " with --seed 7", 0), 0u) << text;
  const run_config::RunConfig again = run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "copy.yaml"));
  EXPECT_EQ(again.seed, 7u);
  EXPECT_DOUBLE_EQ(again.controller.Required("max_speed_mps").AsDouble(), 0.1);
  ASSERT_EQ(again.initial_poses.size(), config.initial_poses.size());
  for (size_t i = 0; i < again.initial_poses.size(); ++i) {
    EXPECT_EQ(again.initial_poses[i].x_m, config.initial_poses[i].x_m);
    EXPECT_EQ(again.initial_poses[i].theta_rad, config.initial_poses[i].theta_rad);
  }
}

TEST_F(OverriddenConfigTest, MistakesNameTheOptionAndTheKey) {
  // A misspelt last key is added, then refused by the config check (the
  // controller section's by RunSession::CheckAgents, in LoadConfig).
  const std::string misspelt = ErrorOf(-1, {"stepz=3"});
  EXPECT_NE(misspelt.find("stepz"), std::string::npos) << misspelt;
  EXPECT_NE(misspelt.find("(with --set stepz=3)"), std::string::npos) << misspelt;
  EXPECT_NE(ErrorOf(-1, {"controler.gain=1"}).find("--set controler.gain: " + path_ + " has no key 'controler'"),
            std::string::npos);
  const std::string bad_value = ErrorOf(-1, {"robots=many"});
  EXPECT_NE(bad_value.find("demo.yaml:3: robots"), std::string::npos) << bad_value;
  EXPECT_NE(bad_value.find("(with --set robots=many)"), std::string::npos) << bad_value;
  EXPECT_NE(ErrorOf(-1, {"robots"}).find("--set robots: expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(ErrorOf(-1, {"robots=2,3"}).find("one value per key here (2 given)"), std::string::npos);
  EXPECT_NE(ErrorOf(4, {"seed=5"}).find("--seed and --set seed=... both set the seed"), std::string::npos);
  EXPECT_EQ(ErrorOf(-1, {"seed=5"}), "(no error)");  // alone, --set seed is just another key
}

TEST_F(OverriddenConfigTest, AMissingFileIsAConfigErrorNamingIt) {
  EXPECT_THROW(config_overrides::OverriddenConfig((dir_ / "nope.yaml").string(), 3, {}), config::ConfigError);
}

}  // namespace
}  // namespace dream::cli

namespace dream::cli {
namespace {

// `--set sim_only=true` lifts the robot limit as the key in the file does,
// for the whole run and for an agent, and the run folder's copy keeps it.
TEST_F(OverriddenConfigTest, SimOnlyCanBeSetFromTheCommandLine) {
  EXPECT_THAT(ErrorOf(-1, {"robots=60"}), ::testing::HasSubstr("add `sim_only: true` to run up to 128 robots"));
  const config_overrides::OverriddenConfig overridden(path_, -1, {"robots=60", "sim_only=true"});
  const config::ControllerConfig agent = overridden.LoadWith(&config::LoadControllerConfig);
  EXPECT_TRUE(agent.sim_only);
  EXPECT_EQ(agent.num_robots, 60);
  const std::string copy = overridden.Text();
  const config::ControllerConfig again =
      config::LoadControllerConfig(config::ConfigNode::LoadString(copy, "copy.yaml"));
  EXPECT_TRUE(again.sim_only);
  EXPECT_EQ(again.num_robots, 60);
  // A quoted value in the file is replaced by the command line's plain one.
  std::ofstream(path_, std::ios::app) << "sim_only: \"no\"\n";
  EXPECT_THAT(ErrorOf(-1, {}), ::testing::HasSubstr("sim_only: expected true or false, got the quoted text"));
  EXPECT_TRUE(config_overrides::OverriddenConfig(path_, -1, {"robots=60", "sim_only=true"})
                  .LoadWith(&config::LoadControllerConfig)
                  .sim_only);
}

}  // namespace
}  // namespace dream::cli
