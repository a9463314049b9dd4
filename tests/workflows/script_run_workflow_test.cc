#include "dream/workflows/script_run_workflow.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

namespace dream::workflows {
namespace {

using ::testing::HasSubstr;

std::string ErrorOf(const std::string& line) {
  try {
    ScriptRunWorkflow::ParseHello(line);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ScriptRunWorkflowTest, ReadsTheRobotsAndWhereTheDriveLeftThem) {
  const auto hello = ScriptRunWorkflow::ParseHello(
      R"({"robots": 2, "startup_steps": 715, "initial_poses": [[-1.2538952016837905, 0.4941969706443189, 0.1], )"
      R"([0.5, -0.25, -3.0]]})");
  EXPECT_EQ(hello.robots, 2);
  EXPECT_EQ(hello.startup_steps, 715);
  ASSERT_EQ(hello.initial_poses.size(), 2u);
  EXPECT_EQ(hello.initial_poses[0][0], -1.2538952016837905);
  EXPECT_EQ(hello.initial_poses[1][2], -3.0);
}

TEST(ScriptRunWorkflowTest, RefusesAHelloItCannotRunNamingTheFieldAndValue) {
  EXPECT_THAT(ErrorOf("not json"), HasSubstr("not a JSON object"));
  EXPECT_THAT(ErrorOf(R"({"robots": 0, "initial_poses": []})"), HasSubstr("robots must be 1..50, got 0"));
  EXPECT_THAT(ErrorOf(R"({"robots": 51, "initial_poses": []})"), HasSubstr("got 51"));
  EXPECT_THAT(ErrorOf(R"({"robots": "2", "initial_poses": []})"), HasSubstr("got \"2\""));
  EXPECT_THAT(ErrorOf(R"({"robots": 2, "initial_poses": [[0, 0, 0]]})"), HasSubstr("one [x, y, theta] per robot (2)"));
  EXPECT_THAT(ErrorOf(R"({"robots": 1, "initial_poses": [[0, "a", 0]]})"),
              HasSubstr("initial_poses[0][1] is not a finite number: \"a\""));
  EXPECT_THAT(ErrorOf(R"({"robots": 1, "initial_poses": [[0, 0]]})"),
              HasSubstr("initial_poses[0] is not [x, y, theta]"));
  EXPECT_THAT(ErrorOf(R"({"robots": 1, "initial_poses": [[0, 0, 0]], "startup_steps": -1})"),
              HasSubstr("startup_steps must be a whole number >= 0, got -1"));
  EXPECT_THAT(ErrorOf(std::string(ScriptRunWorkflow::kMaxHelloBytes + 1, ' ')), HasSubstr("more than 65536 bytes"));
}

TEST(ScriptRunWorkflowTest, TheConfigStartsEveryRobotExactlyWhereTheScriptSaid) {
  ScriptRunWorkflow::Hello hello;
  hello.robots = 2;
  hello.initial_poses = {{0.1 + 0.2, -1.0 / 3.0, std::nextafter(3.0, 0.0)}, {1e-17, -0.0, 2.0 / 7.0}};
  ScriptRunWorkflow::Options options;
  options.script_path = "some dir/my script.py";
  options.seed = 9;
  options.python_runtime_dir = "/opt/dream/python-runtime";
  const YAML::Node config = YAML::Load(ScriptRunWorkflow::ConfigText(hello, options));
  EXPECT_EQ(config["name"].as<std::string>(), "my_script");
  EXPECT_EQ(config["seed"].as<long long>(), 9);
  EXPECT_EQ(config["robots"].as<int>(), 2);
  EXPECT_EQ(config["steps"].as<long long>(), ScriptRunWorkflow::kDefaultSteps);
  // Any finite command, as the official simulator takes it: by the config key, not a magic number.
  EXPECT_EQ(config["world"]["command_limits"].as<std::string>(), "official");
  EXPECT_FALSE(config["world"]["max_abs_v_mps"].IsDefined());
  // The script ends the run: a world key of the config, not a flag set behind it.
  EXPECT_TRUE(config["world"]["script_ends_run"].as<bool>());
  EXPECT_EQ(config["controller"]["module"].as<std::string>(),
            "/opt/dream/python-runtime/rps_dream/robotarium_script.py");
  EXPECT_FALSE(config["controller"]["goal_record"].IsDefined());
  const YAML::Node recorded = YAML::Load(ScriptRunWorkflow::ConfigText(hello, options, "/runs/my script/g.json"));
  EXPECT_EQ(recorded["controller"]["goal_record"].as<std::string>(), "/runs/my script/g.json");
  for (size_t i = 0; i < 2; ++i) {
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(config["initial_poses"][i][k].as<double>(), hello.initial_poses[i][k]) << i << "," << k;
    }
  }
}

/// A file in a fresh temporary folder, removed with it.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text)
      : dir_(std::filesystem::temp_directory_path() /
             ("script_run_workflow_test_" + std::to_string(::getpid()) + "_" + name)) {
    std::filesystem::create_directories(dir_);
    std::ofstream(path()) << text;
  }
  ~TempFile() { std::filesystem::remove_all(dir_); }
  std::string path() const { return (dir_ / "file").string(); }
  std::string dir() const { return dir_.string(); }

 private:
  std::filesystem::path dir_;
};

TEST(ScriptRunWorkflowTest, ASweepsBaseConfigNamesTheScriptAndChecksAsARunConfig) {
  const TempFile script("base", "import rps\n");
  const std::string path = script.dir() + "/go.py";
  std::filesystem::rename(script.path(), path);
  const run_config::RunConfig base = ScriptRunWorkflow::BaseConfig(path, "/opt/dream/python-runtime");
  EXPECT_EQ(base.name, "go");
  EXPECT_EQ(base.script, path);
  EXPECT_EQ(base.seed, 1u);
  EXPECT_THROW(ScriptRunWorkflow::BaseConfig(script.dir() + "/missing.py", "/x"), std::invalid_argument);
}

TEST(ScriptRunWorkflowTest, AConfigNamingTheScriptKeepsItsKeysAndTakesTheHellosRobots) {
  ScriptRunWorkflow::Options options;
  options.script_path = "/s/go.py";
  options.python_runtime_dir = "/opt/dream/python-runtime";
  // A sweep's run: the base config with its seed, name and a --set value.
  std::string text = ScriptRunWorkflow::BaseConfigText("/s/go.py", "/opt/dream/python-runtime");
  text.replace(text.find("name: go"), 8, "name: seed07");
  const TempFile base("with_hello", text);
  ScriptRunWorkflow::Hello hello;
  hello.robots = 2;
  hello.initial_poses = {{0.1 + 0.2, -1.0 / 3.0, 1.0}, {0.5, 0.25, -2.0}};
  options.seed = 7;
  options.steps = 99;
  const YAML::Node config = YAML::Load(ScriptRunWorkflow::WithHello(base.path(), hello, options));
  EXPECT_EQ(config["name"].as<std::string>(), "seed07");
  EXPECT_EQ(config["script"].as<std::string>(), "/s/go.py");
  EXPECT_EQ(config["seed"].as<long long>(), 7);
  EXPECT_EQ(config["steps"].as<long long>(), 99);
  EXPECT_EQ(config["robots"].as<int>(), 2);
  ASSERT_EQ(config["initial_poses"].size(), 2u);
  EXPECT_EQ(config["initial_poses"][0][0].as<double>(), 0.1 + 0.2);
  EXPECT_EQ(config["initial_poses"][0][1].as<double>(), -1.0 / 3.0);
  EXPECT_EQ(config["initial_poses"][1][2].as<double>(), -2.0);
  EXPECT_EQ(config["world"]["command_limits"].as<std::string>(), "official");  // the base config's keys kept
  EXPECT_TRUE(config["world"]["script_ends_run"].as<bool>());
  // Each run's goal record is in its own folder (docs/robotarium-scripts.md#the-goal).
  const YAML::Node rerun = YAML::Load(ScriptRunWorkflow::WithHello(base.path(), hello, options, "/runs/b/g.json"));
  EXPECT_EQ(rerun["controller"]["goal_record"].as<std::string>(), "/runs/b/g.json");
}

// A config naming its script written before world.script_ends_run: its rerun gets the key.
TEST(ScriptRunWorkflowTest, AnOlderConfigNamingTheScriptGetsScriptEndsRun) {
  ScriptRunWorkflow::Options options;
  options.script_path = "/s/go.py";
  const TempFile base("older",
                      "name: go\nscript: /s/go.py\nrobots: 1\ninitial_poses: [[0, 0, 0]]\n"
                      "controller: {kind: python, module: m.py, class: C}\n");
  ScriptRunWorkflow::Hello hello;
  hello.robots = 1;
  hello.initial_poses = {{0.5, 0.25, -2.0}};
  const YAML::Node config = YAML::Load(ScriptRunWorkflow::WithHello(base.path(), hello, options));
  EXPECT_TRUE(config["world"]["script_ends_run"].as<bool>());
}

TEST(ScriptRunWorkflowTest, TheRunIsNamedAfterTheScript) {
  EXPECT_EQ(ScriptRunWorkflow::RunName("/x/go_to_point_si.py"), "go_to_point_si");
  EXPECT_EQ(ScriptRunWorkflow::RunName("a b;c.py"), "a_b_c");
  EXPECT_EQ(ScriptRunWorkflow::RunName(".py"), ".py");
}

}  // namespace
}  // namespace dream::workflows
