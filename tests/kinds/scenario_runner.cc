#include "scenario_runner.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/log_metrics.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/node/run_recorder.h"
#include "dream/node/sim_node.h"
#include "dream/world/unicycle_world.h"
#include "../support/source_tree.h"

namespace dream::agents::scenario {

ScenarioResult RunScenario(run_config::RunConfig config, const std::string& log_name,
                           std::shared_ptr<const agent_host::ControllerRegistry> registry) {
  config.sim.progress_interval_s = 0.0;
  lcm::LcmBus bus("memq://");
  const agent_host::ControllerFactory factory =
      registry ? agent_host::ControllerFactory(config, registry) : agent_host::ControllerFactory(config);
  std::vector<std::unique_ptr<RobotAgent>> robots;
  for (int id = 0; id < config.num_robots; ++id) robots.push_back(factory.Make(id));
  agent_host::AgentHost host(bus, std::move(robots), 1);
  world::UnicycleWorld world(config.world, config.initial_poses, config.obstacles);
  // ctest runs each test as its own process, possibly in parallel: one log per process.
  const std::string log_path =
      ::testing::TempDir() + "/" + log_name + "_scenario_" + std::to_string(::getpid()) + ".lcmlog";
  ScenarioResult result;
  {
    node::RunRecorder recorder(log_path);
    node::SimNode node(bus, world, &recorder, config.sim);
    const std::atomic<bool> stop{false};
    result.outcome = node.Run(stop);
    recorder.Close();
  }
  result.violations = world.violations();
  result.final_poses = world.poses();
  result.metrics = agent_host::MetricsFromLog(factory, run_log::RunLog::Read(log_path));
  for (int id = 0; id < config.num_robots; ++id) {
    result.bad_radio_messages += host.agent(static_cast<size_t>(id)).robot().bad_radio_messages();
  }
  std::remove(log_path.c_str());
  return result;
}

std::string ConfigPath(const std::string& name) { return dream::testing::SourceDir() + "/config/" + name + ".yaml"; }

double Value(const ScenarioResult& run, const std::string& name) {
  const auto it = run.metrics.values.find(name);
  EXPECT_NE(it, run.metrics.values.end()) << name;
  return it == run.metrics.values.end() ? NAN : it->second;
}

}  // namespace dream::agents::scenario
