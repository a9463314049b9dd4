#include <algorithm>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/snapshot_from_messages.h"
#include "dream/agents/framework/robot_agent.h"
#include "dream/agents/framework/world_snapshot.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "dream/run_config/world_of_config.h"
#include "dream/node/world_messages.h"
#include "dream/world/world.h"
#include "fuzz_targets.h"

namespace dream::fuzz {
namespace {

// Steps the world and every agent run: past the thesis parts' start delays
// (20 + id steps), so robots, sensors and radios all run.
constexpr int64_t kSteps = 80;

// The run in closed loop without a bus, as the session's SimNode and agent
// hosts run it: the config's world (realism included), its messages as SimNode
// fills them, every agent, each broadcast delivered to the others. What a robot builds per step from its
// config values is only reached here (a 2^31-sided Voronoi disc, allocated by
// every robot at its first step, was).
void RunClosedLoop(const run_config::RunConfig& run, std::vector<std::unique_ptr<agents::RobotAgent>>& robots) {
  const std::unique_ptr<world::World> world = run_config::WorldOfConfig(run);
  std::vector<world::ObstacleState> scratch;
  obstacles_t obstacles;
  robot_poses_t poses;
  agents::WorldSnapshot snapshot;
  const int64_t steps = std::min<int64_t>(kSteps, run.sim.max_steps);
  for (int64_t step = 0; step < steps; ++step) {
    // What the agents are sent, taken in as an agent host does.
    node::WorldMessages::Fill(*world, &scratch, &obstacles);
    node::WorldMessages::Fill(*world, &poses);
    agent_host::TakeObstacles(obstacles, &snapshot);
    agent_host::TakePoses(poses, &snapshot);
    std::vector<agents::RadioMessage> sent;
    for (auto& robot : robots) {
      const agents::RobotAgent::Output out = robot->Step(snapshot);
      world->SetCommand(robot->id(), {out.command.v_mps, out.command.w_radps});
      if (out.broadcast) sent.push_back(*out.broadcast);
    }
    for (const agents::RadioMessage& message : sent) {
      for (auto& robot : robots) {
        if (robot->id() != message.sender_id) robot->Receive(message);
      }
    }
    world->Step();
  }
}

}  // namespace

void RunConfigTarget(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::unique_ptr<agents::RobotAgent>> robots;
  std::optional<run_config::RunConfig> loaded;
  try {
    loaded = run_config::LoadRunConfig(config::ConfigNode::LoadString(text, "fuzz.yaml"));
    const run_config::RunConfig& run = *loaded;
    // Then what `dream run` builds from it (as tests/reliability/config_mutation_test.cc
    // does): every robot's agent and the metrics. A plugin (a library to load) and
    // kind python (an embedded interpreter per input) are read by code of their own,
    // tested elsewhere; num_robots is at most ControllerConfig::kMaxRobotsSimOnly (128).
    if (!run.plugins.empty() || run.controller.GetString("kind", "") == "python") return;
    const agent_host::ControllerFactory factory(run);
    for (int robot = 0; robot < run.num_robots; ++robot) robots.push_back(factory.Make(robot));
    (void)factory.MakeMetrics();
  } catch (const config::ConfigError& e) {
    if (std::string(e.what()).rfind("fuzz.yaml", 0) != 0)
      Finding("a config error without its file: " + std::string(e.what()));
    return;
  } catch (const std::exception& e) {
    Finding("a config refused by something else than a ConfigError: " + std::string(e.what()));
  }
  // A config that loaded must run: a robot that throws at run time fails
  // its agent (DREAM_FAULT), which the config check should have prevented.
  try {
    RunClosedLoop(*loaded, robots);
  } catch (const std::exception& e) {
    Finding("an accepted config whose world or agents throw when they run: " + std::string(e.what()));
  }
}

}  // namespace dream::fuzz
