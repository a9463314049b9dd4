#pragma once

#include <optional>
#include <string>

#include "dream/agent_host/controller_factory.h"
#include "dream/agents/framework/goal_judgement.h"
#include "dream/agents/framework/metrics_report.h"

namespace dream::agents {

/// The experiment's metrics (factory.MakeMetrics()) computed from a run's
/// log: every DREAM_POSES step in order, with the obstacles last published
/// before it. The same code judges a simulated run and a lab run imported as
/// a log; `dream run` puts the result under "metrics" in summary.json.
/// Undecodable records are skipped. @throws std::runtime_error when the log
/// cannot be opened or ends inside a record.
///
/// `goal`, when given, receives the experiment's success rule applied to the
/// report (ExperimentMetrics::JudgeGoal), or nothing for a kind without one.
MetricsReport MetricsFromLog(const ControllerFactory& factory, const std::string& log_path,
                             std::optional<GoalJudgement>* goal = nullptr);

}  // namespace dream::agents
