#pragma once

#include <iostream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "dream/session/run_session.h"

namespace dream::workflows {

/// What the agent processes of `dream launch` refused (bad messages, other
/// runs, steps out of sequence), each written by `dream-agent --report` and
/// read together after the run: summary.json's "agents" section, and the
/// verdict's reason when they refused anything.
class AgentReports {
 public:
  /// Where the agent of `robot` writes its report, in the run folder `out_dir`.
  static std::string PathFor(const std::string& out_dir, int robot);

  /// Reads (and removes) every robot's report; a report missing or not
  /// readable is listed (the agent died: the world's summary says more).
  static AgentReports Read(const std::string& out_dir, int num_robots);

  /// The agents' refusals (`reports`, Read's), in summary.json's "agents"
  /// section, added by the run's one writer of reports (`session`'s
  /// RunReporter); a run whose agents refused messages is not ready (as one
  /// whose world refused some), so the verdict, the picture and the exit code
  /// say so, and `out` why. Returns the launch's exit code given the
  /// simulator's `sim_exit`.
  static int Merge(const session::RunSession& session, const std::string& out_dir, const AgentReports& reports,
                   int sim_exit, std::ostream& out = std::cout);

  /// The simulator published and logged its verdict on DREAM_VERDICT before
  /// the agents' reports were merged: when they refused something and
  /// summary.json's verdict now says otherwise (a worse verdict, more reasons,
  /// another exit code), it replaces the one the run's log ends on and is
  /// published on `lcm_url`, so the log and a viewer end on summary.json's
  /// (session::VerdictBroadcast::RewriteLoggedVerdict, then Publish). Reports
  /// that refused nothing changed nothing: the log is not read and no bus is
  /// opened; nor is one when the log says summary.json's verdict already. A
  /// failure is logged, never the launch's. Returns whether it published.
  static bool ResendVerdict(const session::RunSession& session, const std::string& out_dir, const AgentReports& reports,
                            const std::string& lcm_url, int exit_code);

  nlohmann::ordered_json section;  ///< summary.json's "agents"
  std::string problem;             ///< what they refused, in one line ("" when nothing)
};

}  // namespace dream::workflows
