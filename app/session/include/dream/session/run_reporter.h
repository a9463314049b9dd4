#pragma once

#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/node/run_outcome.h"
#include "dream/node/run_summary.h"
#include "dream/run_config/run_config.h"
#include "dream/session/run_result.h"
#include "dream/world/run_judgement.h"
#include "dream/world/run_verdict.h"
#include "dream/world/verdict_reason.h"
#include "dream/world/world.h"

namespace dream::session {

/// The one writer of a run's report: summary.json (the run's fields, its
/// experiment metrics, the goal, the verdict with its reasons) and
/// trajectories.png (with the config's goals and the verdict), for every
/// command that leaves a run folder: dream run, sim, lab-replay (through
/// RunSession), dream import (a lab run, through RunSession::Reporter) and
/// dream launch (the agents' reports, AddReasons). A change to summary.json
/// is made here once.
class RunReporter {
 public:
  struct Options {
    /// Where the verdict, the reasons and the outputs' paths are printed.
    std::ostream* report = &std::cout;
    /// The step limit came from --steps: a run it stopped has its goal not judged.
    bool steps_from_command_line = false;
    /// -q: a clean run prints no report (the verdict is in summary.json and
    /// the exit code); a run with anything wrong still prints its whole report.
    bool quiet = false;
    /// The Python runtime (python/), for the metrics and goal a kind computes
    /// itself (ControllerKind::own_metrics: a Python controller's); "": those
    /// are not computed.
    std::string python_runtime_dir;
  };

  /// A run that has ended, its log written to `dir`/run.lcmlog.
  struct Ended {
    const world::World* world = nullptr;  ///< stepped to the run's end: counts, final poses
    node::RunOutcome outcome;
    std::string dir;
    /// Added to summary.json last (e.g. "lab", "lab_replay").
    nlohmann::ordered_json fields = nlohmann::ordered_json::object();
    /// The run's judgement before its goal; none: node::JudgeRun's on the
    /// config, with the verifier's count of robots outside re-counted on the log.
    /// A lab run is judged by the lab verifier's rules on what was declared.
    std::optional<world::RunJudgement> judgement;
  };

  /// `factory` may be null (it could not be built: `factory_error` says why,
  /// and summary.json's metrics.error then). Both must outlive the reporter.
  RunReporter(const run_config::RunConfig& config, const agent_host::ControllerFactory* factory,
              std::string factory_error, Options options);

  /// Reads the log back once, writes summary.json and (after a step or a
  /// finished run) trajectories.png atomically, and prints the verdict.
  RunResult Report(const Ended& ended) const;

  /// Adds reasons found after the run (dream launch: the agents' refusals)
  /// and a section to the summary.json in `dir`: the verdict becomes the
  /// worst of the old and the new reasons', and the picture is drawn again
  /// when it changes. Returns the new verdict.
  /// @throws std::runtime_error naming the file when summary.json cannot be
  ///         read (or holds no verdict) or cannot be written.
  world::RunVerdict AddReasons(const std::string& dir, const std::string& section_key,
                               const nlohmann::ordered_json& section,
                               const std::vector<world::VerdictReason>& reasons) const;

  static constexpr const char* kLogName = "run.lcmlog";
  static constexpr const char* kSummaryName = node::RunSummary::kFileName;
  static constexpr const char* kPictureName = "trajectories.png";
  /// summary.json's violations_located lists at most this many (and counts the rest).
  static constexpr size_t kMaxViolationsListed = 100;

 private:
  struct LogReadBack;
  nlohmann::ordered_json Metrics(const LogReadBack& log) const;
  world::RunJudgement Judge(const Ended& ended, const LogReadBack& log, node::RunSummary* summary) const;
  /// -q and a clean run whose goal was judged: nothing to print.
  bool QuietAbout(const world::RunJudgement& judgement, const nlohmann::ordered_json& goal) const;
  void PrintVerdict(const Ended& ended, const world::RunJudgement& judgement, const nlohmann::ordered_json& goal) const;
  bool DrawPicture(const LogReadBack& log, const std::string& picture_path, world::RunVerdict verdict,
                   const nlohmann::ordered_json& metrics) const;

  const run_config::RunConfig& config_;
  const agent_host::ControllerFactory* factory_;
  std::string factory_error_;
  Options options_;
};

}  // namespace dream::session
