#include "dream/run_config/run_config.h"

#include <gtest/gtest.h>

#include "dream/world/unicycle_world.h"

namespace dream::config {
namespace {

const char* kMinimal = R"(name: demo
seed: 3
robots: 2
steps: 100
initial_poses:
  - [0.0, 0.0, 0.0]
  - [0.5, 0.0, 1.57]
controller:
  kind: go_to_goal
  goals: [[0.1, 0.1], [0.6, 0.1]]
)";

run_config::RunConfig Load(const std::string& text) {
  return run_config::LoadRunConfig(ConfigNode::LoadString(text, "test.yaml"));
}

/// The ConfigError message for `text`, or "" if it loads.
std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(RunConfigTest, MinimalConfigLoadsWithDefaults) {
  const run_config::RunConfig config = Load(kMinimal);
  EXPECT_EQ(config.name, "demo");
  EXPECT_EQ(config.seed, 3u);
  EXPECT_EQ(config.num_robots, 2);
  EXPECT_EQ(config.sim.max_steps, 100);
  EXPECT_EQ(config.sim.mode, config::WorldMode::kLockstep);
  ASSERT_EQ(config.initial_poses.size(), 2u);
  EXPECT_DOUBLE_EQ(config.initial_poses[1].theta_rad, 1.57);
  EXPECT_EQ(config.controller.Required("kind").AsString(), "go_to_goal");
}

TEST(RunConfigTest, GeneratedInitialPosesAreDeterministicForASeed) {
  const std::string text = Replace(Replace(kMinimal, "  - [0.0, 0.0, 0.0]\n  - [0.5, 0.0, 1.57]\n", ""),
                                   "initial_poses:\n", "initial_poses: {generate: {min_spacing_m: 0.4}}\n");
  const run_config::RunConfig a = Load(text);
  const run_config::RunConfig b = Load(text);
  ASSERT_EQ(a.initial_poses.size(), 2u);
  EXPECT_EQ(a.initial_poses[1].x_m, b.initial_poses[1].x_m);
  const run_config::RunConfig c = Load(Replace(text, "seed: 3", "seed: 4"));
  EXPECT_NE(a.initial_poses[1].x_m, c.initial_poses[1].x_m);
}

TEST(RunConfigTest, ObstaclesWithPaths) {
  const run_config::RunConfig config = Load(std::string(kMinimal) + R"(obstacles:
  - center: [1.0, 0.5]
    size: [0.2, 0.3]
  - center: [-1.0, -0.5]
    size: [0.1, 0.1]
    path: {waypoints: [[-1.0, 0.5]], speed_mps: 0.05, mode: ping_pong}
)");
  ASSERT_EQ(config.obstacles.size(), 2u);
  EXPECT_FALSE(config.obstacles[0].path.has_value());
  ASSERT_TRUE(config.obstacles[1].path.has_value());
  EXPECT_EQ(config.obstacles[1].path->mode, world::ObstaclePathMode::kPingPong);
  EXPECT_EQ(config.obstacles[1].id, 1);
}

TEST(RunConfigTest, TooManyRobotsNamesFileLineKeyAndRange) {
  const std::string error = ErrorOf(Replace(kMinimal, "robots: 2", "robots: 51"));
  EXPECT_NE(error.find("test.yaml:3: robots: must be at most 50"), std::string::npos) << error;
  EXPECT_NE(error.find("got 51"), std::string::npos) << error;
  EXPECT_NE(ErrorOf(Replace(kMinimal, "robots: 2", "robots: 0")).find("between 1 and 50"), std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kMinimal, "robots: 2", "robots: two")).find("expected a whole number, got 'two'"),
            std::string::npos);
}

TEST(RunConfigTest, PoseOutsideTheArenaIsRejected) {
  const std::string error = ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[1.7, 0.0, 1.57]"));
  EXPECT_NE(error.find("test.yaml:7: initial_poses[1]"), std::string::npos) << error;
  EXPECT_NE(error.find("outside the arena"), std::string::npos) << error;
}

TEST(RunConfigTest, PoseOnTheWallIsRejectedByTheLabsStartRule) {
  // (1.6, 0) is inside for the world's boundary check (edges included), but
  // half the robot would be outside: dream export would refuse the run.
  const std::string error = ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[1.6, 0.0, 1.57]"));
  EXPECT_NE(error.find("test.yaml:7: initial_poses[1]: robot 1 starts at (1.600, 0.000), closer than its radius "
                       "0.055 m to the arena's wall"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("start_inside_arena"), std::string::npos) << error;
  EXPECT_NE(error.find("x in [-1.545, 1.545], y in [-0.945, 0.945]"), std::string::npos) << error;
  // Exactly the radius from the wall is clear, a tenth of a millimetre less is not.
  EXPECT_EQ(ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[0.5, -0.945, 1.57]")), "");
  EXPECT_NE(ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[0.5, -0.9451, 1.57]")).find("closer than its radius"),
            std::string::npos);
}

TEST(RunConfigTest, GeneratedPosesKeepTheRobotRadiusFromTheWalls) {
  const std::string text = Replace(Replace(kMinimal, "  - [0.0, 0.0, 0.0]\n  - [0.5, 0.0, 1.57]\n", ""),
                                   "initial_poses:\n", "initial_poses: {generate: {wall_margin_m: 0.02}}\n");
  const std::string error = ErrorOf(text);
  EXPECT_NE(error.find("test.yaml:5: initial_poses.generate.wall_margin_m: must be at least 0.055 m (the robot's "
                       "radius)"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("got 0.02"), std::string::npos) << error;
  EXPECT_EQ(ErrorOf(Replace(text, "wall_margin_m: 0.02", "wall_margin_m: 0.055")), "");
}

TEST(RunConfigTest, OverlappingPosesAreRejected) {
  const std::string error = ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[0.1, 0.0, 3.14]"));
  EXPECT_NE(error.find("robots 0 and 1 start in collision"), std::string::npos) << error;
}

TEST(RunConfigTest, PoseInsideAnObstacleIsRejected) {
  // Robot 1 at (0.5, 0) facing up: its collision disc (centre (0.5, 0.025),
  // radius 0.0675 m) reaches into a block whose bottom edge is at y = 0.05.
  const std::string error = ErrorOf(std::string(kMinimal) +
                                    "obstacles:\n  - center: [-1.0, 0.5]\n    size: [0.2, 0.2]\n"
                                    "  - center: [0.5, 0.15]\n    size: [0.4, 0.2]\n");
  EXPECT_NE(error.find("test.yaml:7: initial_poses[1]: robot 1 starts inside obstacle 1"), std::string::npos) << error;
  EXPECT_NE(error.find("at (0.500, 0.000, 1.570)"), std::string::npos) << error;
  EXPECT_NE(error.find("radius 0.0675 m"), std::string::npos) << error;
  EXPECT_NE(error.find("obstacles[1] (centre (0.500, 0.150), size 0.400 x 0.200 m, at step 0)"), std::string::npos)
      << error;
  // Touching counts, as in the world: the disc of robot 0 (centre (0.025, 0))
  // just reaches a block whose left edge is 0.0675 m away.
  const std::string touching =
      ErrorOf(std::string(kMinimal) + "obstacles:\n  - center: [0.1925, -0.5]\n    size: [0.2, 1.0]\n");
  EXPECT_NE(touching.find("test.yaml:6: initial_poses[0]: robot 0 starts inside obstacle 0"), std::string::npos)
      << touching;
  // Just clear of it loads.
  EXPECT_EQ(ErrorOf(std::string(kMinimal) + "obstacles:\n  - center: [0.1926, -0.5]\n    size: [0.2, 1.0]\n"), "");
}

TEST(RunConfigTest, MovingObstacleMayCrossAStartPoseLater) {
  // Starts clear of both robots, passes over them at steps > 0: allowed, the
  // run counts any contact as the Robotarium would.
  EXPECT_EQ(ErrorOf(std::string(kMinimal) + "obstacles:\n  - center: [-1.0, 0.0]\n    size: [0.2, 0.2]\n"
                                            "    path: {waypoints: [[1.0, 0.0]], speed_mps: 0.1}\n"),
            "");
  EXPECT_NE(ErrorOf(std::string(kMinimal) + "obstacles:\n  - center: [0.0, 0.0]\n    size: [0.2, 0.2]\n"
                                            "    path: {waypoints: [[1.0, 0.0]], speed_mps: 0.1}\n")
                .find("robot 0 starts inside obstacle 0"),
            std::string::npos);
}

TEST(RunConfigTest, GeneratedPosesAvoidObstacles) {
  // Thirty robots around a block covering a fifth of the arena (without the
  // obstacles in the generator, seed 3 puts several on it).
  std::string text = Replace(Replace(kMinimal, "  - [0.0, 0.0, 0.0]\n  - [0.5, 0.0, 1.57]\n", ""), "initial_poses:\n",
                             "initial_poses: {generate: {min_spacing_m: 0.25}}\n");
  text = Replace(text, "robots: 2", "robots: 30") + "obstacles:\n  - center: [0.0, 0.0]\n    size: [1.6, 0.8]\n";
  text = Replace(text, "goals: [[0.1, 0.1], [0.6, 0.1]]", "goals: []");
  const run_config::RunConfig config = Load(text);
  ASSERT_EQ(config.initial_poses.size(), 30u);
  world::UnicycleWorld world(config.world, config.initial_poses, config.obstacles);
  world.Step();
  EXPECT_EQ(world.violations(), world::ViolationCounts{});
}

TEST(RunConfigTest, ImpossibleGenerationNamesTheKeyAndWhatToChange) {
  std::string text = Replace(Replace(kMinimal, "  - [0.0, 0.0, 0.0]\n  - [0.5, 0.0, 1.57]\n", ""), "initial_poses:\n",
                             "initial_poses:\n  generate: {min_spacing_m: 0.25}\n");
  text += "obstacles:\n  - center: [0.0, 0.0]\n    size: [3.2, 2.0]\n";
  const std::string error = ErrorOf(text);
  EXPECT_NE(error.find("test.yaml:6: initial_poses.generate: cannot generate initial poses"), std::string::npos)
      << error;
  EXPECT_NE(error.find("placed only 0 of 2 robots"), std::string::npos) << error;
  EXPECT_NE(error.find("smaller or fewer obstacles"), std::string::npos) << error;
  EXPECT_NE(error.find("or list one [x, y, theta] per robot under initial_poses"), std::string::npos) << error;
  // Without an initial_poses key the poses are generated too; the message
  // names the key to add.
  const std::string implicit = ErrorOf(Replace(text, "initial_poses:\n  generate: {min_spacing_m: 0.25}\n", ""));
  EXPECT_NE(implicit.find(": initial_poses: cannot generate initial poses"), std::string::npos) << implicit;
}

TEST(RunConfigTest, WrongPoseCountAndShape) {
  EXPECT_NE(ErrorOf(Replace(kMinimal, "  - [0.5, 0.0, 1.57]\n", "")).find("one [x, y, theta] per robot (2), got 1"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[0.5, 0.0]")).find("expected [x, y, theta]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kMinimal, "[0.5, 0.0, 1.57]", "[0.5, .nan, 0]")).find("finite"), std::string::npos);
}

TEST(RunConfigTest, AScriptRunNamesItsScriptAPythonFile) {
  EXPECT_EQ(Load(kMinimal).script, "");
  EXPECT_EQ(Load(std::string(kMinimal) + "script: /home/me/go.py\n").script, "/home/me/go.py");
  EXPECT_NE(ErrorOf(std::string(kMinimal) + "script: /home/me/go.yaml\n")
                .find("test.yaml:11: script: expected the path of a Robotarium script (a .py file), got "
                      "'/home/me/go.yaml'"),
            std::string::npos)
      << ErrorOf(std::string(kMinimal) + "script: /home/me/go.yaml\n");
}

TEST(RunConfigTest, UnknownKeysAreTyposAndSayWhatIsAllowed) {
  const std::string error = ErrorOf(Replace(kMinimal, "steps: 100", "stpes: 100"));
  EXPECT_NE(error.find("test.yaml:4: stpes: unknown key "
                       "(did you mean 'steps'?); allowed keys here: name, seed"),
            std::string::npos)
      << error;
  EXPECT_NE(ErrorOf(std::string(kMinimal) + "world: {mode: fast}\n")
                .find("unknown world mode 'fast'; allowed: "
                      "lockstep, realtime"),
            std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kMinimal) + "world: {agent_timeout_s: -1}\n")
                .find("test.yaml:11: world.agent_timeout_s: must be > 0, got -1"),
            std::string::npos);
  // A resend every microsecond flooded memq's queue and lost the agents' answers.
  for (const char* interval : {"1e-6", "0", "-1"}) {
    EXPECT_NE(ErrorOf(std::string(kMinimal) + "world: {resend_interval_s: " + interval + "}\n")
                  .find(std::string("test.yaml:11: world.resend_interval_s: must be >= 0.01 s (more often floods the "
                                    "bus), got ") +
                        interval),
              std::string::npos)
        << interval;
  }
  EXPECT_NE(ErrorOf(Replace(kMinimal, "steps: 100", "steps: -5")).find("test.yaml:4: steps: must be >= 1, got -5"),
            std::string::npos);
}

// world.command_limits: robotarium (the default: absurd commands refused) or official (any finite
// command, as the official simulator takes it: Robotarium script runs).
TEST(RunConfigTest, CommandLimitsAreTheRobotariumsOrTheOfficialSimulatorsByName) {
  const run_config::RunConfig robotarium = Load(kMinimal);
  EXPECT_DOUBLE_EQ(robotarium.sim.max_abs_v_mps, 10.0);
  EXPECT_DOUBLE_EQ(robotarium.sim.max_abs_w_radps, 100.0);
  const run_config::RunConfig official = Load(std::string(kMinimal) + "world: {command_limits: official}\n");
  EXPECT_DOUBLE_EQ(official.sim.max_abs_v_mps, config::SimNodeOptions::kOfficialCommandLimit);
  EXPECT_DOUBLE_EQ(official.sim.max_abs_w_radps, config::SimNodeOptions::kOfficialCommandLimit);
  const std::string bad = ErrorOf(std::string(kMinimal) + "world: {command_limits: offical}\n");
  EXPECT_NE(bad.find("test.yaml:11: world.command_limits: unknown world command_limits 'offical' (did you mean "
                     "'official'?); allowed: robotarium, official"),
            std::string::npos)
      << bad;
  const std::string both = ErrorOf(std::string(kMinimal) + "world: {command_limits: official, max_abs_v_mps: 5}\n");
  EXPECT_NE(both.find("world.max_abs_v_mps: is not taken with command_limits: official"), std::string::npos) << both;
}

// world.script_ends_run: a Robotarium script's run ends with its script (dream run SCRIPT.py writes
// it); a key like any, checked, and refused in a config that names no script.
TEST(RunConfigTest, ScriptEndsRunIsAWorldKeyOfAScriptsRunOnly) {
  EXPECT_FALSE(Load(kMinimal).sim.script_ends_run);
  const std::string script = std::string(kMinimal) + "script: /home/me/go.py\n";
  EXPECT_TRUE(Load(script + "world: {script_ends_run: true}\n").sim.script_ends_run);
  EXPECT_FALSE(Load(script + "world: {script_ends_run: false}\n").sim.script_ends_run);
  const std::string bad = ErrorOf(script + "world: {script_ends_run: sometimes}\n");
  EXPECT_NE(bad.find("test.yaml:12: world.script_ends_run"), std::string::npos) << bad;
  EXPECT_NE(bad.find("sometimes"), std::string::npos) << bad;
  const std::string lonely = ErrorOf(std::string(kMinimal) + "world: {script_ends_run: true}\n");
  EXPECT_NE(lonely.find("test.yaml:11: world.script_ends_run: only a Robotarium script's run (script:) ends with its "
                        "script"),
            std::string::npos)
      << lonely;
}

TEST(RunConfigTest, BadObstacles) {
  EXPECT_NE(ErrorOf(std::string(kMinimal) + "obstacles:\n  - center: [0, 0]\n    size: [0, 1]\n").find("obstacles[0]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kMinimal) +
                    "obstacles:\n  - center: [0, 0]\n    size: [1, 1]\n    path: {waypoints: [[1, 1]], "
                    "speed_mps: 0.1, mode: bounce}\n")
                .find("unknown path mode 'bounce'; allowed: loop, ping_pong"),
            std::string::npos);
}

// DREAM_OBSTACLES carries at most lcm::MessageLimits::kObstacles: a run with
// more would have every agent refuse the world's obstacles.
TEST(RunConfigTest, ObstacleCountIsBounded) {
  const auto obstacles = [](size_t count) {
    std::string text = "obstacles:\n";
    for (size_t i = 0; i < count; ++i)
      text += "  - {center: [" + std::to_string(i % 2000) + ", 50], size: [0.1, 0.1]}\n";
    return text;
  };
  EXPECT_EQ(Load(std::string(kMinimal) + obstacles(run_config::RunConfig::kMaxObstacles)).obstacles.size(),
            run_config::RunConfig::kMaxObstacles);
  const std::string error = ErrorOf(std::string(kMinimal) + obstacles(run_config::RunConfig::kMaxObstacles + 1));
  EXPECT_NE(error.find(": obstacles: at most 10000 obstacles, got 10001"), std::string::npos) << error;
}

TEST(RunConfigTest, UnsafeRunNamesAreRejected) {
  // The name becomes a folder under runs/: no paths, no shell or script text.
  EXPECT_NE(ErrorOf(Replace(kMinimal, "name: demo", "name: ../../etc")).find("not a plain name"), std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kMinimal, "name: demo", "name: \"a'b\"")).find("not a plain name"), std::string::npos);
}

TEST(RunConfigTest, MissingFileAndBrokenYaml) {
  try {
    run_config::LoadRunConfigFile("/nonexistent/run.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/run.yaml: cannot open"), std::string::npos);
  }
  try {
    ConfigNode::LoadString("name: [unclosed\n", "broken.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.yaml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not valid YAML"), std::string::npos) << e.what();
  }
  EXPECT_NE(ErrorOf("- just\n- a list\n").find("must be a YAML mapping"), std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kMinimal, "name: demo\n", "")).find("name: missing; this key is required"),
            std::string::npos);
}

}  // namespace
}  // namespace dream::config
