#include "dream/workflows/sweep_workflow.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <numeric>
#include <ostream>
#include <thread>

#include "dream/config/config_node.h"
#include "dream/files/stopped.h"
#include "dream/files/atomic_file.h"
#include "dream/files/output_folder.h"
#include "dream/files/output_folder_lock.h"
#include "dream/world/printf_text.h"
#include "dream/workflows/prepared_sweep.h"
#include "dream/workflows/slurm_jobs.h"
#include "dream/workflows/slurm_submission.h"
#include "dream/workflows/sweep_folder.h"
#include "collected_sweep.h"
#include "replace_file.h"
#include "sweep_inputs.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Facts = std::vector<std::pair<std::string, std::string>>;

/// True when `dir` holds a sweep (its table, plan or runs).
bool HoldsSweep(const fs::path& dir) {
  std::error_code error;
  return fs::exists(dir / "sweep.csv", error) || fs::exists(dir / "sweep.md", error) ||
         fs::exists(dir / "runs", error) || fs::exists(dir / SweepFolder::kPlanFile, error);
}

std::string Quoted(const std::string& text) {
  return text.find_first_of(" \t'\"$[]{}*?;&|<>()\\") == std::string::npos ? text : "'" + text + "'";
}

/// The command line that reproduces this sweep (for sweep.md).
std::string ReproducingCommand(const SweepSettings& s, const std::string& seeds, int jobs, const std::string& out_dir) {
  std::string line = "dream sweep " + Quoted(s.config_path) + " --seeds " + seeds;
  for (const std::string& set : s.sets) line += " --set " + Quoted(set);
  for (const std::string& zip : s.zips) line += " --zip " + Quoted(zip);
  if (jobs > 0) line += " --jobs " + std::to_string(jobs);
  if (s.steps > 0) line += " --steps " + std::to_string(s.steps);
  if (s.engine != SweepSettings::Engine::kLocal) line += " --engine " + SweepSettings::EngineName(s.engine);
  for (const std::string& option : s.slurm_options) line += " --slurm-option=" + Quoted(option);
  return line + " --out " + Quoted(out_dir);
}

/// What the table's summary block says of how the runs ran.
std::string ParallelText(const std::string& engine, int jobs, int cores) {
  if (engine == "slurm")
    return "Slurm job array, " + (jobs > 0 ? std::to_string(jobs) + " at a time" : std::string("no limit"));
  if (engine == "plan") return "planned for another scheduler (commands.txt)";
  return std::to_string(jobs) + " (" + std::to_string(cores) + " cores)";
}

/// Creates the sweep folder (a given --out's parent must exist, as for every
/// --out) and locks it (a second sweep into it is refused while this one
/// runs); an earlier sweep's table, commands and jobs must not pass for this one's.
SweepFolder MakeFolder(const SweepSettings& s, const std::string& base_name, const std::string& out_dir) {
  files::OutputFolder(
      out_dir, s.out_dir.empty() ? files::OutputFolder::Parents::kCreate : files::OutputFolder::Parents::kMustExist)
      .MakeSubfolder("runs");
  files::OutputFolderLock::HoldUntilExit(out_dir);
  if (s.out_dir.empty() && out_dir != "sweeps/" + base_name) {
    spdlog::warn("sweeps/{} holds an earlier sweep, so this one goes to {} (--out DIR to choose)", base_name, out_dir);
  }
  const SweepFolder folder(out_dir);
  std::error_code error;
  for (const char* stale :
       {"sweep.csv", "sweep.md", SweepFolder::kCommandsFile, SlurmJobs::kJobsFile, SweepInputs::kFileName}) {
    fs::remove(folder.Path(stale), error);
  }
  return folder;
}

/// sweep.json: what status, resume and table need to know of the start.
nlohmann::json SettingsJson(const SweepSettings& s, const std::string& base_name, const std::string& command, int jobs,
                            int cores, long long time_limit_minutes, const std::string& dream_path) {
  return {{"title", "Sweep of " + base_name + " (" + s.config_path + ")"},
          {"command", command},
          {"config", fs::absolute(s.config_path).lexically_normal().string()},
          {"seeds", s.seeds},
          {"sets", s.sets},
          {"zips", s.zips},
          {"steps", s.steps},
          {"engine", SweepSettings::EngineName(s.engine)},
          {"jobs", jobs},
          {"cores", cores},
          {"run_timeout_s", s.run_timeout_s},
          {"slurm_options", s.slurm_options},
          {"slurm_time_limit_minutes", time_limit_minutes},
          {"dream", dream_path}};
}

const std::atomic<bool>& NeverStop() {
  static const std::atomic<bool> never{false};
  return never;
}

}  // namespace

SweepWorkflow::SweepWorkflow(Environment environment) : env_(std::move(environment)) {}

int SweepWorkflow::cores() const {
  return env_.cores > 0 ? env_.cores : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::string SweepWorkflow::ChooseFolder(const std::string& out_dir, const std::string& base_name) {
  if (!out_dir.empty()) return out_dir;
  const std::string base = "sweeps/" + base_name;
  std::string chosen = base;
  for (int n = 2; HoldsSweep(chosen); ++n) chosen = base + "_" + std::to_string(n);
  return chosen;
}

SweepOutcome SweepWorkflow::Start(const SweepSettings& s, const run_config::RunConfig& base) {
  using Engine = SweepSettings::Engine;
  if (!(s.run_timeout_s > 0.0)) throw std::invalid_argument("--timeout must be > 0");
  if (s.engine != Engine::kSlurm && !s.slurm_options.empty()) {
    throw std::invalid_argument("--slurm-option is for --engine slurm only");
  }
  if (s.engine == Engine::kSlurm && env_.commands == nullptr) throw std::logic_error("no command runner for Slurm");
  // --- everything checked before anything is written or started ---
  const std::string out_dir = ChooseFolder(s.out_dir, base.name);
  SweepFolder::CheckFolderPath(out_dir);
  if (s.engine == Engine::kSlurm) SlurmSubmission::CheckFolderPath(SweepFolder(out_dir).dir());
  const PreparedSweep prepared(s, base, out_dir);
  for (const std::string& warning : prepared.startup_warnings()) spdlog::warn("{}", warning);
  const SweepPlan& plan = prepared.plan();
  const int jobs = s.engine == Engine::kLocal ? (s.jobs > 0 ? s.jobs : cores()) : s.jobs;

  const SweepFolder folder = MakeFolder(s, base.name, out_dir);
  folder.WritePlan(plan);
  folder.WriteRunScript(env_.dream_path);
  const std::string command =
      ReproducingCommand(s, prepared.seeds_text(), s.engine == Engine::kLocal ? jobs : s.jobs, out_dir);
  const long long time_limit = SlurmSubmission::DefaultTimeLimitMinutes(prepared.max_steps());
  folder.WriteSettings(SettingsJson(s, base.name, command, jobs, cores(), time_limit, env_.dream_path));
  SweepInputs::Record(folder, s.config_path);  // what resume checks before it adds runs to this table
  std::vector<size_t> all(plan.runs().size());
  std::iota(all.begin(), all.end(), size_t{0});
  if (s.engine == Engine::kLocal) return RunAll(folder, prepared, s, jobs, command, base.name);

  // Not synced one by one (thousands of files): a crash before the page
  // cache reaches the disk leaves a config a run refuses, and resume redoes it.
  for (size_t index : all) prepared.WriteRun(folder, index);
  if (s.engine == Engine::kPlan) {
    folder.WriteCommands(all);
    if (env_.out != nullptr) {
      *env_.out << "planned " << all.size() << " runs: " << folder.Path(SweepFolder::kCommandsFile)
                << " holds one shell command per run; run them on any scheduler, then: dream sweep table " << out_dir
                << std::endl;
    }
    SweepOutcome outcome;
    outcome.out_dir = out_dir;
    outcome.runs = all.size();
    outcome.kind = SweepOutcome::Kind::kPlanned;
    return outcome;
  }
  return Submit(folder, all, {s.jobs, time_limit, s.slurm_options, env_.dream_path, "dream-sweep-" + base.name});
}

SweepOutcome SweepWorkflow::RunAll(const SweepFolder& folder, const PreparedSweep& prepared, const SweepSettings& s,
                                   int jobs, const std::string& command, const std::string& base_name) {
  const SweepPlan& plan = prepared.plan();
  const size_t count = plan.runs().size();
  spdlog::info(
      "sweep: {} runs of {} ({} seeds{}), {} at a time on {} cores -> {}", count, base_name, prepared.seed_count(),
      s.sets.empty() && s.zips.empty() ? std::string()
                                       : " x " + std::to_string(count / prepared.seed_count()) + " parameter sets",
      jobs, cores(), folder.dir());
  std::vector<size_t> all(count);
  std::iota(all.begin(), all.end(), size_t{0});
  SweepTable table(plan.parameter_keys(), count);
  const Clock::time_point started = Clock::now();
  const bool done = RunLocally(
      folder, plan, all, jobs, s.run_timeout_s, [&](size_t index) { prepared.WriteRun(folder, index); }, table);
  if (!done)
    spdlog::warn("sweep interrupted: {} of {} runs ended, the rest never started", table.results().size(), count);
  const double wall_s = std::chrono::duration<double>(Clock::now() - started).count();
  WriteTable(folder, table, "Sweep of " + base_name + " (" + s.config_path + ")",
             {{"command", command},
              {"runs in parallel", ParallelText("local", jobs, cores())},
              {"wall time", world::PrintfText("%.1f s", wall_s) + (done ? "" : " (interrupted)")}});
  SweepOutcome outcome;
  outcome.out_dir = folder.dir();
  outcome.runs = count;
  outcome.kind = done ? SweepOutcome::Kind::kFinished : SweepOutcome::Kind::kInterrupted;
  outcome.summary = table.Summary();
  return outcome;
}

SweepOutcome SweepWorkflow::Submit(const SweepFolder& folder, const std::vector<size_t>& indices,
                                   const SlurmSubmission::Options& options) {
  SlurmSubmission submission(folder, *env_.commands);
  const SlurmSubmission::Submitted submitted = submission.Submit(indices, options);
  SweepOutcome outcome;
  outcome.out_dir = folder.dir();
  outcome.runs = indices.size();
  outcome.kind = SweepOutcome::Kind::kSubmitted;
  outcome.jobs = submitted.array_jobs;
  outcome.jobs.push_back(submitted.table_job);
  if (env_.out != nullptr) {
    std::string arrays;
    for (const std::string& id : submitted.array_jobs) arrays += (arrays.empty() ? "" : ", ") + id;
    *env_.out << "submitted " << indices.size() << " runs to Slurm: job array " << arrays << ", then job "
              << submitted.table_job << " writes " << folder.Path("sweep.md") << "\nfollow it: dream sweep status "
              << folder.dir() << std::endl;
  }
  return outcome;
}

bool SweepWorkflow::RunLocally(const SweepFolder& folder, const SweepPlan& plan, const std::vector<size_t>& indices,
                               int jobs, double run_timeout_s, const std::function<void(size_t)>& write_run,
                               SweepTable& table) {
  if (!env_.make_job_runner) throw std::logic_error("SweepWorkflow: no job runner for the local engine");
  const std::unique_ptr<JobRunner> runner = env_.make_job_runner(jobs, run_timeout_s);
  const std::vector<SweepPlan::Run>& runs = plan.runs();
  size_t finished = 0;
  auto prepare = [&](size_t k) {
    const SweepPlan::Run& run = runs[indices[k]];
    write_run(run.index);
    const std::string dir = folder.RunDir(run.name);
    // A private bus: runs of a script at once must not hear each other (a config's run is on memq:// anyway).
    return JobRunner::Job{{env_.dream_path, "run", dir + "/config.yaml", "--out", dir, "--private-bus"},
                          dir + "/output.txt"};
  };
  auto on_finished = [&](const JobRunner::Finished& done) {
    const SweepPlan::Run& run = runs[indices[done.index]];
    if (done.timed_out)
      spdlog::warn("{}: still running after {:.0f} s (--timeout); stopped", run.Label(), run_timeout_s);
    if (folder.RunIsLocked(run.name)) {
      // Another process runs it (its own run.sh or dream run), which writes its record: not ours to touch.
      spdlog::warn("{}: left alone, another process holds its folder ({})", run.Label(), done.start_error);
      ++finished;
      table.Add(SweepRunResult::NotRun(run, SweepFolder::kRunningReason));
      return;
    }
    RunExit exit;
    exit.exit_code = done.exit_code;
    exit.wall_time_s = done.wall_time_s;
    exit.timed_out = done.timed_out;
    if (!done.start_error.empty()) exit.problem = "could not start: " + done.start_error;
    try {
      folder.WriteRunExit(run.name, exit);  // for dream sweep table / resume later
    } catch (const std::exception& e) {
      spdlog::error("{}: {}", run.Label(), e.what());
    }
    SweepRunResult result = folder.JudgeRun(run, exit);
    ++finished;
    if (env_.progress && env_.out != nullptr) {
      std::string line = "[" + std::to_string(finished) + "/" + std::to_string(indices.size()) + "] " + run.Label() +
                         ": " + result.OutcomeText();
      if (result.status == SweepRunResult::Status::kRan) line += ", " + std::to_string(result.steps) + " steps";
      *env_.out << line << std::endl;
    }
    table.Add(std::move(result));
  };
  return runner->Run(indices.size(), env_.stop != nullptr ? *env_.stop : NeverStop(), prepare, on_finished);
}

void SweepWorkflow::WriteTable(const SweepFolder& folder, const SweepTable& table, const std::string& title,
                               const Facts& facts) const {
  const std::string csv_path = folder.Path("sweep.csv");
  const std::string md_path = folder.Path("sweep.md");
  files::WriteFileAtomically(csv_path, table.Csv());
  files::WriteFileAtomically(md_path, table.Markdown(title, facts));
  if (env_.out == nullptr) return;
  std::string by_value = table.ByValueMarkdown(50);
  *env_.out << "\n"
            << table.SummaryMarkdown(facts) << (by_value.empty() ? "" : "\n" + by_value) << "\ntable: " << md_path
            << "\ncsv:   " << csv_path << "\n";
}

CollectedSweep SweepWorkflow::Collect(const SweepFolder& folder, bool check_busy) const {
  CollectedSweep c{folder.ReadPlan(), folder.ReadSettings(), {}, {}, {}, false, {}, {}, {}};
  const auto config = c.settings.find("config");
  try {
    c.changed_inputs = SweepInputs::Changed(
        folder, config != c.settings.end() && config->is_string() ? config->get<std::string>() : "",
        &c.unchecked_inputs);
  } catch (const std::runtime_error& e) {
    c.changed_inputs = {std::string(SweepInputs::kFileName) + " (" + e.what() +
                        ")"};  // a damaged record proves nothing
  }
  const SlurmJobs jobs(folder);
  std::map<size_t, SlurmTaskState> states;
  if (!jobs.arrays().empty()) states = jobs.TaskStates(env_.commands, &c.note);
  // A local sweep working in the folder holds its lock: its unfinished runs are not lost.
  c.busy = check_busy && jobs.arrays().empty() && !files::OutputFolderLock::TryHoldUntilExit(folder.dir());
  c.results.reserve(c.plan.runs().size());
  for (const SweepPlan::Run& run : c.plan.runs()) {
    // Thousands of runs' files: Ctrl-C stops the table, status or resume here, before it writes anything.
    if (env_.stop != nullptr && env_.stop->load()) throw files::Stopped();
    const auto it = states.find(run.index);
    c.slurm.push_back(it == states.end() ? std::nullopt : std::optional<SlurmTaskState>(it->second));
    // While a local sweep works here its runs are its children: no one else's lock to look for.
    c.locked.push_back(!c.busy && folder.RunIsLocked(run.name));
    c.results.push_back(folder.CollectRun(run, c.slurm.back(), c.busy, c.locked.back()));
  }
  SweepRunResult::RefuseSharedRunIds(c.results);
  return c;
}

}  // namespace dream::workflows
