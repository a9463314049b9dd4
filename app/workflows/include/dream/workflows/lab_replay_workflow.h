#pragma once

#include <atomic>
#include <iostream>
#include <optional>
#include <ostream>
#include <string>

#include "dream/bridge/command_agreement.h"
#include "dream/session/exit_code.h"

namespace dream::workflows {

/// `dream lab-replay` (and check-submission's replay): a lab run imported by
/// `dream import` replayed as the world (bridge::LabReplayWorld: the lab's
/// poses step by step), the config's controllers answering it as agents, in
/// this process (session::RunSession::RunWithAgents) or elsewhere
/// (`world_only`, agents started with dream agent). Recorded, judged and
/// reported as every run; summary.json adds `lab_replay`: the agents'
/// commands beside the lab's (bridge::CommandAgreement).
class LabReplayWorkflow {
 public:
  struct Options {
    std::string lab_dir;      ///< a folder written by dream import (run.lcmlog, config.yaml)
    std::string out_dir;      ///< empty: runs/<name>_lab_replay (or _2, ... when that holds a run)
    bool overwrite = false;   ///< replace a run already in the output folder
    std::string lcm_url;      ///< empty: memq:// with in-process agents, else LCM_DEFAULT_URL
    long long steps = 0;      ///< 0: the whole lab run
    std::string mode;         ///< empty: the config's
    bool world_only = false;  ///< no in-process agents: they run elsewhere (dream agent)
    /// A Robotarium script's lab run (its config names `script:`): the
    /// caller started the script on `lcm_url` as the agent of every robot
    /// (dream lab-replay of it, docs/robotarium-scripts.md); implies world_only.
    /// Without it such a run is refused: its RobotariumScript agents drive nothing.
    bool script_agent = false;
    /// The Python runtime, for a Python controller's own metrics ("": none).
    std::string python_runtime_dir;
    /// Ends the replay early when set (Ctrl-C); none: it ends by itself.
    const std::atomic<bool>* stop = nullptr;
  };

  /// How the replay ended: its exit code (as dream run's) and, once the world
  /// has stepped, how the agents' commands compare with the lab's.
  struct Result {
    session::ExitCode exit_code = session::kExitOk;
    std::optional<bridge::CommandAgreement> agreement;
  };

  /// `report` takes the verdict and the outputs' paths (RunSession::Options::report).
  explicit LabReplayWorkflow(std::ostream& report = std::cout) : report_(&report) {}

  /// @throws std::runtime_error naming the file when the lab run or its config
  ///         cannot be replayed (robots disagree, no step); config::ConfigError
  ///         for a controller section that cannot run.
  Result Replay(const Options& options) const;

 private:
  std::ostream* report_;
};

}  // namespace dream::workflows
