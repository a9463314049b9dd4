#pragma once

#include <optional>

#include "dream/agent_host/controller_factory.h"
#include "dream/agents/framework/goal_judgement.h"
#include "dream/agents/framework/metrics_report.h"
#include "dream/run_log/run_log.h"

namespace dream::agent_host {

/// The experiment's metrics (factory.MakeMetrics()) computed from a run's
/// log: every DREAM_POSES step in order, with the obstacles of its step, each
/// turned into the WorldSnapshot the agents were given (TakePoses,
/// TakeObstacles). The same code judges a simulated run and a lab run
/// imported as a log; `dream run` puts the result under "metrics" in
/// summary.json. Messages that do not decode are not in `log`.
///
/// `goal`, when given, receives the experiment's success rule applied to the
/// report (ExperimentMetrics::JudgeGoal), or nothing for a kind without one.
agents::MetricsReport MetricsFromLog(const ControllerFactory& factory, const run_log::RunLog& log,
                                     std::optional<agents::GoalJudgement>* goal = nullptr);

}  // namespace dream::agent_host
