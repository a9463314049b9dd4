#pragma once
// What the workflows' tests share: a simulated run folder written by
// RunSession (as dream run writes it: config.yaml, run.lcmlog, summary.json,
// trajectories.png) and its export, made once per test binary.

#include <string>

namespace dream::workflows::testing {

/// runs/go_to_goal as `dream run config/go_to_goal.yaml` writes it, agents in
/// this process on memq://; made once.
const std::string& SimulatedRun();

/// SimulatedRun() exported with the default options (track); made once.
const std::string& SimulatedExport();

}  // namespace dream::workflows::testing
