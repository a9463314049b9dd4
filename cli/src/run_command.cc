#include <spdlog/spdlog.h>

#include <random>

#include "commands.h"
#include "dream/agents/agent_host.h"
#include "dream/agents/controller_factory.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "run_output.h"

namespace dream::cli {

int RunEmbedded(const RunArgs& args) {
  const config::RunConfig config = LoadConfig(args);
  // One process: the world and every agent share one bus, memq:// unless the
  // user asks for a real transport.
  lcm::LcmBus bus(args.lcm_url.empty() ? "memq://" : lcm::ResolveLcmUrl(args.lcm_url));
  const std::string out_dir = PrepareOutputDir(args, config);
  const agents::ControllerFactory factory(config);
  std::vector<std::unique_ptr<agents::RobotAgent>> robots;
  for (int id = 0; id < config.num_robots; ++id) robots.push_back(factory.Make(id));
  agents::AgentHost host(bus, std::move(robots), NewAgentId());
  return RunWorld(bus, config, out_dir);
}

int RunSimOnly(const RunArgs& args) {
  const config::RunConfig config = LoadConfig(args);
  lcm::LcmBus bus(lcm::ResolveLcmUrl(args.lcm_url));
  const std::string out_dir = PrepareOutputDir(args, config);
  return RunWorld(bus, config, out_dir);
}

}  // namespace dream::cli
