#pragma once

#include <string>

#include "dream/run_config/run_config.h"

namespace dream::session {

/// One line saying that a run is not in the ideal world, printed when it
/// starts and in its report, so nobody mistakes a `lab` run for an official
/// one: "realism: lab (not the official simulator's ideal world: ...;
/// the models: summary.json realism)". The preset's name when the models equal
/// one, else "custom". Empty for the ideal world.
std::string RealismNotice(const run_config::RunConfig& config);

}  // namespace dream::session
