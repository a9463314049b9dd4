#include <spdlog/spdlog.h>

#include <csignal>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include <filesystem>

#include "command_line.h"
#include "dream/session/run_reporter.h"
#include "dream/session/run_session.h"
#include "dream/session/verdict_broadcast.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "dream/world/run_verdict.h"
#include "dream/world/verdict_reason.h"
#include "dream/files/file_text.h"
#include "dream/files/output_folder_lock.h"
#include "commands.h"
#include "dream/process/data_files.h"
#include "dream/process/process_group.h"
#include "run_output.h"
#include "shared_options.h"

namespace dream::cli {

// Measured: the simulator and a C++ agent peak at 13 open descriptors under
// udpm (LCM's sockets and pipes, the log, the lock, stdio); room for Python agents.
constexpr int kDescriptorsPerProcess = 24;

namespace {

// Where each agent process writes what it refused (dream-agent --report);
// merged into summary.json and removed.
std::filesystem::path AgentReportDir(const std::string& out_dir) {
  return std::filesystem::path(out_dir) / ".agent_reports";
}

std::string AgentReportPath(const std::string& out_dir, int robot) {
  return (AgentReportDir(out_dir) / ("robot_" + std::to_string(robot) + ".json")).string();
}

/// What the agents' reports say together: summary.json's "agents" section,
/// and what they refused in one line ("" when nothing).
struct AgentReports {
  nlohmann::ordered_json section;
  std::string problem;
};

// Reads (and removes) each agent's report.
AgentReports ReadAgentReports(const std::string& out_dir, int num_robots) {
  nlohmann::ordered_json bad = nlohmann::ordered_json::object();
  std::map<std::string, std::string> first_bad;  // channel -> the first agent's first refusal there
  std::set<std::string> other_runs;
  long long out_of_sequence = 0;
  long long refused = 0;
  std::vector<int> missing;
  for (int robot = 0; robot < num_robots; ++robot) {
    try {
      // Bounded like every file read whole: a report is a few hundred bytes.
      const nlohmann::json report = nlohmann::json::parse(files::ReadFileText(AgentReportPath(out_dir, robot)));
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

// The simulator published its verdict on DREAM_VERDICT; the agents' reports
// made it worse: the bus hears summary.json's now, so a viewer ends on it.
void ResendVerdict(const session::RunSession& session, const std::string& summary_path, const std::string& lcm_url,
                   int exit_code) {
  try {
    lcm::LcmBus bus(lcm::ResolveLcmUrl(lcm_url));
    session::VerdictBroadcast::Resend(bus, summary_path, session.config().world.time_step_s,
                                      static_cast<ExitCode>(exit_code));
  } catch (const std::exception& e) {
    spdlog::warn("the verdict with the agents' reports was not published on DREAM_VERDICT: {}", e.what());
  }
}

// The agents' refusals, in summary.json's "agents" section, added by the
// run's one writer of reports; a run whose agents refused messages is not
// ready (as one whose world refused some), so the verdict, the picture and
// the exit code say so. Returns the launch's exit code.
int MergeAgentReports(const session::RunSession& session, const std::string& out_dir, const std::string& lcm_url,
                      int sim_exit) {
  const AgentReports reports = ReadAgentReports(out_dir, session.config().num_robots);
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
    return kExitRunFailed;
  }
  if (reasons.empty()) return sim_exit;
  std::cout << "Not ready for the Robotarium: " << reports.problem << " (summary.json agents)\n"
            << "verdict: " << world::RunVerdictName(verdict) << " (with the agents' reports, which the simulator's "
            << "report above could not know; summary.json verdict_reasons)\n";
  const int exit_code = sim_exit == kExitOk ? kExitNotReady : sim_exit;
  ResendVerdict(session, summary_path, lcm_url, exit_code);
  return exit_code;
}

}  // namespace

int RunLaunch(const RunArgs& args) {
  process::ProcessGroup::RequireDescriptors(kDescriptorsPerProcess);
  // Check the config here, so a mistake is reported once, not by N+1 children.
  const std::unique_ptr<session::RunSession> session = OpenRunSession(args);
  const run_config::RunConfig& config = session->config();
  CheckStartupDrive(config);
  // Chosen once, here: the simulator gets it as --out, so a numbered folder
  // (runs/<name>_2) is not chosen again, differently, by the child.
  const std::string out_dir = PrepareOutputDir(args, config);
  const std::string self = process::SelfExecutable();
  std::vector<std::string> common = {args.config_path};
  if (!args.lcm_url.empty()) common.push_back("--lcm-url=" + args.lcm_url);
  // The same overrides for the simulator and every agent, so all build the
  // same run (agents read the config too: robots, controller, seed).
  if (args.seed >= 0) common.push_back("--seed=" + std::to_string(args.seed));
  for (const std::string& set : args.sets) common.insert(common.end(), {"--set", set});
  // The children log (and show progress) as quietly or verbosely as this process.
  if (!spdlog::should_log(spdlog::level::info)) common.push_back("--quiet");
  if (spdlog::should_log(spdlog::level::debug)) common.push_back("--verbose");

  process::ProcessGroup children;
  std::vector<std::string> sim_argv = {self, "sim"};
  sim_argv.insert(sim_argv.end(), common.begin(), common.end());
  sim_argv.push_back("--out=" + out_dir);  // holds no run now (an earlier one was refused or removed)
  if (args.steps != 0) sim_argv.push_back("--steps=" + std::to_string(args.steps));
  if (!args.mode.empty()) sim_argv.push_back("--mode=" + args.mode);
  if (args.all_steps) sim_argv.push_back("--all-steps");
  if (args.pace >= 0.0) sim_argv.push_back("--pace=" + std::to_string(args.pace));
  // The simulator writes the folder this process has locked: it inherits the lock.
  const int lock_fd = files::OutputFolderLock::DescriptorOf(out_dir);
  const pid_t sim = children.Start(
      sim_argv, std::string(),
      {std::string(files::OutputFolderLock::kInheritedVariable) + "=" + std::to_string(lock_fd)}, lock_fd);
  std::filesystem::create_directories(AgentReportDir(out_dir));
  std::vector<pid_t> agents;
  for (int id = 0; id < config.num_robots; ++id) {
    std::vector<std::string> agent_argv = {process::DataFiles::AgentBinary()};
    agent_argv.insert(agent_argv.end(), common.begin(), common.end());
    agent_argv.push_back("--robots=" + std::to_string(id));
    agent_argv.push_back("--report=" + AgentReportPath(out_dir, id));
    agents.push_back(children.Start(agent_argv));
  }
  spdlog::info("launched the simulator and {} agent processes", agents.size());

  int sim_exit = -1;
  while ((sim_exit = children.WaitFor(sim, 0.1)) < 0) {
    if (StopFlag().load()) children.SignalAll(SIGINT);
  }
  int failed_agents = 0;
  for (pid_t agent : agents) {
    const int code = children.WaitFor(agent, 5.0);
    if (code != 0) ++failed_agents;
  }
  if (failed_agents > 0) spdlog::warn("{} agent process(es) did not exit cleanly", failed_agents);
  if (sim_exit == kExitInterrupted) return sim_exit;
  return MergeAgentReports(*session, out_dir, args.lcm_url, sim_exit);
}

void DeclareLaunchCommand(CommandLine& line) {
  AddRunCommand(line, "launch",
                "Run the simulator and one agent process per robot over udpm.\n"
                "Example: dream launch config/go_to_goal.yaml --seed 7",
                RunLaunch, "LCM URL (default $LCM_DEFAULT_URL)");
}

}  // namespace dream::cli
