#include <algorithm>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/agents/framework/robot_agent.h"
#include "dream/agents/framework/world_snapshot.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/config/run_config.h"
#include "fuzz_targets.h"

namespace dream::fuzz {
namespace {

// Steps every agent runs on the start poses: past the thesis parts' start
// delays (20 + id steps), so robots, sensors and radios all run.
constexpr int64_t kAgentSteps = 80;

agents::WorldSnapshot StartSnapshot(const config::RunConfig& run) {
  agents::WorldSnapshot world;
  for (const sim::Pose2& pose : run.initial_poses) {
    world.poses.emplace_back(pose.x_m, pose.y_m, pose.theta_rad);
    world.velocities.emplace_back(0.0, 0.0);
  }
  for (const sim::RectangleObstacleSpec& spec : run.obstacles) {
    world.obstacles.push_back({spec.id, spec.center_m, {spec.width_m, spec.height_m}, Eigen::Vector2d::Zero()});
  }
  return world;
}

// A few steps of every agent on the start poses (no world: nobody moves),
// every broadcast delivered to the others, as an agent host would: what a
// robot builds per step from its config values is only reached here (a
// 2^31-sided Voronoi disc, allocated by every robot at its first step, was).
void StepAgents(const config::RunConfig& run, std::vector<std::unique_ptr<agents::RobotAgent>>& robots) {
  agents::WorldSnapshot world = StartSnapshot(run);
  if (world.num_robots() != run.num_robots) return;
  const int64_t steps = std::min<int64_t>(kAgentSteps, run.sim.max_steps);
  for (int64_t step = 0; step < steps; ++step) {
    world.step = step;
    std::vector<agents::RadioMessage> sent;
    for (auto& robot : robots) {
      const agents::RobotAgent::Output out = robot->Step(world);
      if (out.broadcast) sent.push_back(*out.broadcast);
    }
    for (const agents::RadioMessage& message : sent) {
      for (auto& robot : robots) {
        if (robot->id() != message.sender_id) robot->Receive(message);
      }
    }
  }
}

}  // namespace

void RunConfigTarget(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::unique_ptr<agents::RobotAgent>> robots;
  std::optional<config::RunConfig> loaded;
  try {
    loaded = config::LoadRunConfig(config::ConfigNode::LoadString(text, "fuzz.yaml"));
    const config::RunConfig& run = *loaded;
    // Then what `dream run` builds from it (as tests/reliability/config_mutation_test.cc
    // does): every robot's agent and the metrics. A plugin (a library to load) and
    // kind python (an embedded interpreter per input) are read by code of their own,
    // tested elsewhere; num_robots is at most ControllerConfig::kMaxRobots (50).
    if (!run.plugins.empty() || run.controller.GetString("kind", "") == "python") return;
    const agents::ControllerFactory factory(run);
    for (int robot = 0; robot < run.num_robots; ++robot) robots.push_back(factory.Make(robot));
    (void)factory.MakeMetrics();
  } catch (const config::ConfigError& e) {
    if (std::string(e.what()).rfind("fuzz.yaml", 0) != 0) Finding("a config error without its file: " + std::string(e.what()));
    return;
  } catch (const std::exception& e) {
    Finding("a config refused by something else than a ConfigError: " + std::string(e.what()));
  }
  // A config that loaded must run: a robot that throws at run time fails
  // its agent (DREAM_FAULT), which the config check should have prevented.
  try {
    StepAgents(*loaded, robots);
  } catch (const std::exception& e) {
    Finding("an accepted config whose agents throw when they run: " + std::string(e.what()));
  }
}

}  // namespace dream::fuzz
