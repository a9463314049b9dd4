#include "dream/workflows/agent_reports.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "dream/files/file_text.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/session/exit_code.h"
#include "dream/session/run_reporter.h"
#include "dream/session/verdict_broadcast.h"
#include "dream/world/run_verdict.h"
#include "dream/world/verdict_reason.h"

namespace dream::workflows {
namespace {

// Where each agent process writes what it refused (dream-agent --report);
// merged into summary.json and removed.
std::filesystem::path AgentReportDir(const std::string& out_dir) {
  return std::filesystem::path(out_dir) / ".agent_reports";
}

}  // namespace

std::string AgentReports::PathFor(const std::string& out_dir, int robot) {
  return (AgentReportDir(out_dir) / ("robot_" + std::to_string(robot) + ".json")).string();
}

AgentReports AgentReports::Read(const std::string& out_dir, int num_robots) {
  nlohmann::ordered_json bad = nlohmann::ordered_json::object();
  std::map<std::string, std::string> first_bad;  // channel -> the first agent's first refusal there
  std::set<std::string> other_runs;
  long long out_of_sequence = 0;
  long long refused = 0;
  std::vector<int> missing;
  for (int robot = 0; robot < num_robots; ++robot) {
    try {
      // Bounded like every file read whole: a report is a few hundred bytes.
      const nlohmann::json report = nlohmann::json::parse(files::ReadFileText(PathFor(out_dir, robot)));
      for (const auto& [channel, count] : report.at("bad_messages").items()) {
        const long long n = count.get<long long>();
        bad[channel] = (bad.contains(channel) ? bad[channel].get<long long>() : 0) + n;
        refused += n;
      }
      if (report.contains("bad_message_first")) {
        for (const auto& [channel, what] : report.at("bad_message_first").items()) {
          if (!what.is_string()) continue;
          first_bad.emplace(channel, what.get<std::string>() + " (the agent of robot " + std::to_string(robot) + ")");
        }
      }
      for (const auto& run : report.at("other_runs")) other_runs.insert(run.get<std::string>());
      out_of_sequence += report.at("steps_out_of_sequence").get<long long>();
    } catch (const std::exception&) {
      missing.push_back(robot);  // the agent died or could not write it: the world's summary says more
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(AgentReportDir(out_dir), ignored);
  AgentReports reports;
  reports.section = {{"bad_messages", bad},
                     {"other_runs", other_runs},
                     {"steps_out_of_sequence", out_of_sequence},
                     {"reports_missing", missing}};
  if (refused == 0 && other_runs.empty() && out_of_sequence == 0) return reports;
  reports.problem = "the agents refused " + std::to_string(refused) + " message(s)";
  // Which channels, how many, and what the first refusal was: forged world
  // messages and a flaky link read differently.
  int named = 0;
  for (const auto& [channel, count] : bad.items()) {
    if (named++ == 3) {
      reports.problem += "; ...";
      break;
    }
    reports.problem += (named == 1 ? ": " : "; ") + channel + ": " + std::to_string(count.get<long long>());
    const auto first = first_bad.find(channel);
    if (first != first_bad.end()) reports.problem += ", first refused: " + first->second;
  }
  if (!other_runs.empty()) reports.problem += ", heard " + std::to_string(other_runs.size()) + " other run(s)";
  if (out_of_sequence > 0) {
    reports.problem += ", ignored " + std::to_string(out_of_sequence) + " step(s) out of sequence";
  }
  return reports;
}

// The agents' refusals, in summary.json's "agents" section, added by the
// run's one writer of reports; a run whose agents refused messages is not
// ready (as one whose world refused some), so the verdict, the picture and
// the exit code say so. Returns the launch's exit code.
int AgentReports::Merge(const session::RunSession& session, const std::string& out_dir, const AgentReports& reports,
                        int sim_exit, std::ostream& out) {
  const std::string summary_path = out_dir + "/" + session::RunReporter::kSummaryName;
  if (!std::filesystem::exists(summary_path)) {
    spdlog::warn("{}: cannot add the agents' reports (the simulator wrote no summary)", summary_path);
    return sim_exit;
  }
  std::vector<world::VerdictReason> reasons;
  if (!reports.problem.empty()) {
    reasons.push_back({"agent_bad_messages", world::RunVerdict::kNotReady, reports.problem,
                       "summary.json agents; the launch's output names each channel"});
  }
  world::RunVerdict verdict = world::RunVerdict::kClean;
  try {
    verdict = session.Reporter().AddReasons(out_dir, "agents", reports.section, reasons);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return session::kExitRunFailed;
  }
  if (reasons.empty()) return sim_exit;
  out << "Not ready for the Robotarium: " << reports.problem << " (summary.json agents)\n"
      << "verdict: " << world::RunVerdictName(verdict) << " (with the agents' reports, which the simulator's "
      << "report above could not know; summary.json verdict_reasons)\n";
  return sim_exit == session::kExitOk ? session::kExitNotReady : sim_exit;
}

bool AgentReports::ResendVerdict(const session::RunSession& session, const std::string& out_dir,
                                 const AgentReports& reports, const std::string& lcm_url, int exit_code) {
  if (reports.problem.empty()) return false;  // Merge added no reason: the world's verdict stands as logged
  if (!std::filesystem::exists(out_dir + "/" + session::RunReporter::kSummaryName)) return false;  // Merge said so
  try {
    const std::optional<run_verdict_t> changed = session::VerdictBroadcast::RewriteLoggedVerdict(
        out_dir + "/" + session::RunReporter::kSummaryName, session.config().world.time_step_s,
        static_cast<session::ExitCode>(exit_code), out_dir + "/" + session::RunReporter::kLogName);
    if (!changed) return false;
    lcm::LcmBus bus(lcm::ResolveLcmUrl(lcm_url));
    session::VerdictBroadcast::Publish(bus, *changed);
    return true;
  } catch (const std::exception& e) {
    spdlog::warn("the verdict with the agents' reports is not in the run's log nor on DREAM_VERDICT: {}", e.what());
  }
  return false;
}

}  // namespace dream::workflows
