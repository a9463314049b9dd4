#include <cstdint>
#include <exception>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/config/run_config.h"
#include "fuzz_targets.h"

namespace dream::fuzz {

void RunConfigTarget(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const config::RunConfig run = config::LoadRunConfig(config::ConfigNode::LoadString(text, "fuzz.yaml"));
    // Then what `dream run` builds from it (as tests/reliability/config_mutation_test.cc
    // does): every robot's agent and the metrics. A plugin (a library to load) and
    // kind python (an embedded interpreter per input) are read by code of their own,
    // tested elsewhere; num_robots is at most ControllerConfig::kMaxRobots (50).
    if (!run.plugins.empty() || run.controller.GetString("kind", "") == "python") return;
    const agents::ControllerFactory factory(run);
    for (int robot = 0; robot < run.num_robots; ++robot) (void)factory.Make(robot);
    (void)factory.MakeMetrics();
  } catch (const config::ConfigError& e) {
    if (std::string(e.what()).rfind("fuzz.yaml", 0) != 0) Finding("a config error without its file: " + std::string(e.what()));
  } catch (const std::exception& e) {
    Finding("a config refused by something else than a ConfigError: " + std::string(e.what()));
  }
}

}  // namespace dream::fuzz
