#pragma once

#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/config/config_node.h"

namespace dream::kind_api {

/// Reads the optional `hrvo:` mapping of a controller section:
///     hrvo: {variant: exact | thesis, safety_radius_m: 0.24, check_boundaries: true, boundary_horizon_s: 1.0}
/// over `defaults`. @throws config::ConfigError naming the key and value.
agents::HrvoRobotParams ReadHrvoRobotParams(const config::ConfigNode& section, agents::HrvoRobotParams defaults = {});

}  // namespace dream::kind_api
