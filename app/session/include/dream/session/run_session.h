#pragma once

#include <atomic>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/node/run_recorder.h"
#include "dream/session/run_reporter.h"
#include "dream/session/run_result.h"
#include "dream/world/world.h"

namespace dream::session {

/// One run of a world, from its config to its outputs: what every command
/// that runs a world (dream run, sim, lab-replay, and the simulator process
/// of dream launch) goes through, so they record, judge and report alike.
///
/// It builds the run's ControllerFactory once (loading the config's plugins
/// once), for the agents the command hosts, the metrics and the picture.
/// Run() writes the run folder: config.yaml, run.lcmlog, summary.json and
/// trajectories.png, each atomically (docs/run-outputs.md), shows progress
/// while the world steps, and prints the verdict with its reasons; the
/// summary and the picture through Reporter() (RunReporter).
class RunSession {
 public:
  /// A world other than the config's own (dream lab-replay's
  /// LabReplayWorld), made once the run's recorder exists.
  struct GivenWorld {
    std::function<std::unique_ptr<world::World>(node::RunRecorder& recorder)> make;
    /// What the world adds to summary.json, asked once the run has ended; may be empty.
    std::function<nlohmann::ordered_json(const world::World& world)> summary_fields;
    /// Logged when the run starts: what runs, and where its agents are.
    std::string start_line;
  };

  /// Where a run's outputs go.
  struct Folder {
    std::string dir;          ///< exists, chosen (and locked) by the command
    std::string config_text;  ///< what config.yaml holds: enough to rerun the run
  };

  struct Options {
    /// The step limit came from --steps: a run it stopped has its goal not judged.
    bool steps_from_command_line = false;
    /// -q: a clean run prints no report (the verdict is in summary.json and
    /// the exit code); a run with anything wrong still prints its whole report.
    bool quiet = false;
    /// Where the verdict, the reasons and the outputs' paths are printed.
    std::ostream* report = &std::cout;
    /// Ends the run early when set (Ctrl-C); none: the run ends by itself.
    const std::atomic<bool>* stop = nullptr;
    /// The Python runtime, for a Python controller's own metrics (RunReporter::Options).
    std::string python_runtime_dir;
  };

  /// Builds the factory of `config`'s controller. A factory that cannot be
  /// built is remembered, not thrown (factory_error()): a command that hosts
  /// or checks agents refuses to run then (CheckAgents), and a run that goes
  /// ahead with agents elsewhere reports the error under metrics.
  RunSession(run_config::RunConfig config, Options options);
  explicit RunSession(run_config::RunConfig config);
  ~RunSession();

  RunSession(const RunSession&) = delete;
  RunSession& operator=(const RunSession&) = delete;

  const run_config::RunConfig& config() const { return config_; }
  /// The run's one factory; null when it could not be built.
  const agent_host::ControllerFactory* factory() const { return factory_.get(); }
  /// Why the factory could not be built ("" when it was).
  const std::string& factory_error() const { return factory_error_; }

  /// Checks the controller section as far as can be done before a run
  /// (hosting::HostedAgents::Check with this session's factory): the kind and
  /// its keys, and for a kind of the Python runtime its module, class and own
  /// keys, bounded by world.start_timeout_s and ended by Options::stop.
  /// @throws config::ConfigError naming file, line and key.
  void CheckAgents() const;

  /// Runs the config's world (world.realism off: the official world; on:
  /// the realistic world, with true and measured poses both recorded) on
  /// `lcm` until the run ends, then judges and reports it.
  RunResult Run(lcm::LcmInterface& lcm, const Folder& folder);
  /// The same with `world` instead of the config's. A session runs once:
  /// @throws std::logic_error when called again.
  RunResult Run(lcm::LcmInterface& lcm, const Folder& folder, const GivenWorld& world);
  /// The same with every robot's agent hosted on `bus` for the run
  /// (hosting::HostedAgents, in the runtime the kind says: dream run,
  /// lab-replay with its agents, export --calibration), built with this
  /// session's factory and bounded by the config's world time-outs. They
  /// are started once, after every check of the run (a second run of the
  /// session, the folder's files, the world made): a refused run starts none.
  RunResult RunWithAgents(lcm::LcmBus& bus, const Folder& folder);
  RunResult RunWithAgents(lcm::LcmBus& bus, const Folder& folder, const GivenWorld& world);

  /// The run's one writer of summary.json and trajectories.png, with this
  /// session's config, factory and options: what Run() reports through, and
  /// what reports a run that ran elsewhere (dream import's lab run, the
  /// agents' reports dream launch adds). Valid while the session lives.
  RunReporter Reporter() const;

 private:
  struct Stepped;
  /// The config's own world (the start-up drive first with world.start: placed).
  GivenWorld OwnWorld();
  Stepped Step(lcm::LcmInterface& lcm, const Folder& folder, const GivenWorld& world);
  RunResult Report(const Stepped& stepped, const std::string& dir);
  /// Whether the run's log gets its DREAM_VERDICT appended (a log written whole).
  static bool LogKeepsVerdict(const Stepped& stepped);

  run_config::RunConfig config_;
  Options options_;
  std::unique_ptr<agent_host::ControllerFactory> factory_;
  std::string factory_error_;
  bool ran_ = false;
};

}  // namespace dream::session
