#include "dream/session/sim_only_notice.h"

namespace dream::session {

std::string SimOnlyNotice(const config::ControllerConfig& config) {
  if (!config.sim_only) return "";
  constexpr int kSimulatorLimit = config::ControllerConfig::kMaxRobots;
  const std::string beyond =
      config.num_robots > kSimulatorLimit ? ", beyond the Robotarium's " + std::to_string(kSimulatorLimit) : "";
  // After debug()'s words, which may say the script "will run on the Robotarium".
  return "sim-only run: " + std::to_string(config.num_robots) + " robots" + beyond + " (`sim_only: true` in " +
         config.source + "): it never goes to the Robotarium, whatever debug() says above; dream export refuses it";
}

}  // namespace dream::session
