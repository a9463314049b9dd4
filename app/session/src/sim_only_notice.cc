#include "dream/session/sim_only_notice.h"

namespace dream::session {

std::string SimOnlyNotice(const config::ControllerConfig& config) {
  if (!config.sim_only) return "";
  using config::ControllerConfig;
  const std::string beyond = config.num_robots > ControllerConfig::kMaxRobots
                                 ? ", beyond the Robotarium's " + std::to_string(ControllerConfig::kMaxRobots)
                                 : "";
  return "sim-only run: " + std::to_string(config.num_robots) + " robots" + beyond +
         " (declared `sim_only: true` in " + config.source + ": it never goes to the lab; dream export refuses it)";
}

}  // namespace dream::session
