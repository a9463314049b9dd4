#pragma once

#include <string>

#include "dream/config/controller_config.h"

namespace dream::session {

/// One line of a run's report saying that the run was declared for
/// simulation only, so nobody mistakes it for a lab-ready run: "sim-only
/// run: 100 robots, beyond the Robotarium's 50 (`sim_only: true` in FILE):
/// it never goes to the Robotarium, ...". Empty for a run without
/// `sim_only: true`.
std::string SimOnlyNotice(const config::ControllerConfig& config);

}  // namespace dream::session
