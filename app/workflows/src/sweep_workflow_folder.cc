// SweepWorkflow's commands on an existing sweep folder: resume, table, status.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <ostream>

#include "dream/config/config_node.h"
#include "dream/files/output_folder_lock.h"
#include "dream/workflows/prepared_sweep.h"
#include "dream/workflows/slurm_jobs.h"
#include "dream/workflows/slurm_submission.h"
#include "dream/workflows/sweep_folder.h"
#include "dream/workflows/sweep_workflow.h"
#include "collected_sweep.h"
#include "replace_file.h"
#include "sweep_inputs.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

std::string Text(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

long long Number(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<long long>() : 0;
}

std::vector<std::string> Strings(const nlohmann::json& object, const char* key) {
  std::vector<std::string> words;
  const auto it = object.find(key);
  if (it == object.end() || !it->is_array()) return words;
  for (const nlohmann::json& word : *it) {
    if (word.is_string()) words.push_back(word.get<std::string>());
  }
  return words;
}

std::string Joined(const std::vector<std::string>& words) {
  std::string text;
  for (size_t i = 0; i < words.size(); ++i) text += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
  return text;
}

/// What status and table say of inputs changed since the sweep was planned.
std::string ChangedInputsNote(const CollectedSweep& c) {
  if (c.changed_inputs.empty()) return "";
  return Joined(c.changed_inputs) + " changed since the sweep was planned; dream sweep resume refuses it";
}

std::vector<std::pair<std::string, std::string>> FactsOf(const nlohmann::json& settings) {
  const std::string engine = Text(settings, "engine");
  const long long jobs = Number(settings, "jobs");
  std::string parallel;
  if (engine == "slurm") {
    parallel = "Slurm job array, " + (jobs > 0 ? std::to_string(jobs) + " at a time" : std::string("no limit"));
  } else if (engine == "plan") {
    parallel = "planned for another scheduler (commands.txt)";
  } else {
    parallel = std::to_string(jobs) + " (" + std::to_string(Number(settings, "cores")) + " cores)";
  }
  return {{"command", Text(settings, "command")}, {"runs in parallel", parallel}};
}

/// The sweep as it was started (sweep.json), to make the configs of runs
/// whose folders were never written (a local sweep stopped before them).
SweepSettings SettingsOf(const nlohmann::json& settings, const std::string& dir,
                         const std::string& python_runtime_dir) {
  SweepSettings s;
  s.python_runtime_dir = python_runtime_dir;
  s.config_path = Text(settings, "config");
  s.seeds = Text(settings, "seeds");
  s.sets = Strings(settings, "sets");
  s.zips = settings.contains("zips") ? Strings(settings, "zips") : std::vector<std::string>{};  // older sweeps had none
  s.steps = Number(settings, "steps");
  s.out_dir = dir;
  return s;
}

/// The runs of `todo` whose folders were never written (a local sweep
/// stopped with Ctrl-C before them) get their configs made again from the
/// base config, which must still give the same plan; null when none needs it.
std::unique_ptr<PreparedSweep> ConfigsToWriteAgain(const SweepFolder& folder, const CollectedSweep& c,
                                                   const std::vector<size_t>& todo,
                                                   const std::string& python_runtime_dir) {
  std::error_code error;
  const auto missing = std::find_if(todo.begin(), todo.end(), [&](size_t index) {
    return !fs::exists(folder.RunDir(c.plan.runs()[index].name) + "/config.yaml", error);
  });
  if (missing == todo.end()) return nullptr;
  const SweepSettings settings = SettingsOf(c.settings, folder.dir(), python_runtime_dir);
  run_config::RunConfig base =
      run_config::LoadRunConfig(config::ConfigNode::LoadString(settings.BaseConfigText(), settings.config_path));
  if (settings.steps > 0) base.sim.max_steps = settings.steps;
  auto prepared = std::make_unique<PreparedSweep>(settings, base, folder.dir());
  const std::vector<SweepPlan::Run>& again = prepared->plan().runs();
  for (size_t i = 0; i < c.plan.runs().size(); ++i) {
    if (again.size() != c.plan.runs().size() || again[i].name != c.plan.runs()[i].name) {
      throw std::runtime_error(settings.config_path + " no longer gives the plan of " +
                               folder.Path(SweepFolder::kPlanFile) + " (run " + c.plan.runs()[i].name +
                               "); start a new sweep");
    }
  }
  return prepared;
}

/// The runs of `c` that resume runs again: every one without a complete
/// result, except those still running (`running` counts them).
/// @throws std::runtime_error, before anything is touched, when inputs of
///         the sweep changed since it was planned, runs are still queued in
///         Slurm, or a run folder to redo is a link.
std::vector<size_t> RunsToResume(const SweepFolder& folder, const CollectedSweep& c, size_t* running) {
  // Runs of other inputs must not join this table (nothing is touched before these checks).
  if (!c.changed_inputs.empty()) {
    throw std::runtime_error(folder.dir() + ": " + Joined(c.changed_inputs) +
                             " changed since the sweep was planned, so its runs would not be one experiment's; "
                             "put them back, or start a new sweep");
  }
  if (!c.unchecked_inputs.empty()) spdlog::warn("{}: {}", folder.dir(), c.unchecked_inputs);
  size_t queued = 0;
  for (const auto& state : c.slurm) queued += state && state->Queued() ? 1 : 0;
  if (queued > 0) {
    throw std::runtime_error(std::to_string(queued) + " runs of " + folder.dir() +
                             " are still pending or running in Slurm; wait for them (dream sweep status " +
                             folder.dir() + ") or scancel them, then resume");
  }
  std::vector<size_t> todo;
  for (size_t i = 0; i < c.results.size(); ++i) {
    const SweepRunResult& r = c.results[i];
    if (c.locked[i]) {
      ++*running;  // its dream run still works there: never cleared, never run twice
    } else if (r.status != SweepRunResult::Status::kRan) {
      const std::string problem = folder.RunFolderProblem(r.run.name);
      if (!problem.empty()) {
        throw std::runtime_error("resume refused: " + problem +
                                 " (replaced after the sweep was planned?); "
                                 "remove it, and resume runs the run again");
      }
      todo.push_back(r.run.index);
    }
  }
  if (*running > 0) {
    spdlog::warn(
        "{} runs of {} are still running (a process holds their folders): left alone; "
        "dream sweep status {} says when they end",
        *running, folder.dir(), folder.dir());
  }
  return todo;
}

}  // namespace

SweepOutcome SweepWorkflow::Table(const std::string& dir) {
  const SweepFolder folder(dir);
  const CollectedSweep c = Collect(folder, true);
  SweepTable table(c.plan.parameter_keys(), c.plan.runs().size());
  for (const SweepRunResult& result : c.results) table.Add(result);
  if (!c.note.empty()) spdlog::warn("{}", c.note);
  if (!ChangedInputsNote(c).empty()) spdlog::warn("{}: {}", folder.dir(), ChangedInputsNote(c));
  std::string title = Text(c.settings, "title");
  WriteTable(folder, table, title.empty() ? "Sweep " + folder.dir() : title, FactsOf(c.settings));
  SweepOutcome outcome;
  outcome.out_dir = folder.dir();
  outcome.summary = table.Summary();
  return outcome;
}

SweepStatusReport SweepWorkflow::Status(const std::string& dir) {
  const SweepFolder folder(dir);
  const CollectedSweep c = Collect(folder, true);
  SweepStatusReport report;
  report.out_dir = dir;
  report.engine = Text(c.settings, "engine");
  report.planned = c.results.size();
  report.note = c.note;
  if (!ChangedInputsNote(c).empty()) report.note += (report.note.empty() ? "" : "; ") + ChangedInputsNote(c);
  for (size_t i = 0; i < c.results.size(); ++i) {
    const SweepRunResult& r = c.results[i];
    if (r.success) ++report.succeeded;
    switch (r.status) {
      case SweepRunResult::Status::kRan:
        ++report.finished;
        continue;
      case SweepRunResult::Status::kFailed:
        ++report.failed;
        break;
      case SweepRunResult::Status::kInterrupted:
        ++report.interrupted;
        break;
      case SweepRunResult::Status::kNotRun:
        if (c.locked[i] || (c.slurm[i] && c.slurm[i]->state == SlurmTaskState::State::kRunning)) {
          ++report.running;
        } else if ((c.slurm[i] && c.slurm[i]->Queued()) || c.busy) {
          ++report.pending;  // queued in Slurm, or waiting its turn in a local sweep
        } else {
          ++report.not_started;
        }
        break;
    }
    // Grouped by the reason's first words, so "exit 4: ..." lines of different runs still add up.
    const std::string why = r.problem.substr(0, r.problem.find(':'));
    ++report.problems[why.empty() ? "no reason given" : why];
  }
  return report;
}

SweepOutcome SweepWorkflow::Resume(const std::string& dir, const ResumeSettings& rs) {
  const SweepFolder folder(dir);
  if (!fs::is_regular_file(folder.Path(SweepFolder::kPlanFile))) {
    throw std::runtime_error(folder.dir() + " holds no sweep (no " + SweepFolder::kPlanFile + ")");
  }
  SweepFolder::CheckFolderPath(folder.dir());
  files::OutputFolderLock::HoldUntilExit(folder.dir());  // refused while a local sweep works in it
  const CollectedSweep c = Collect(folder, false);
  size_t running = 0;
  const std::vector<size_t> todo = RunsToResume(folder, c, &running);
  std::string engine = rs.engine.empty() ? Text(c.settings, "engine") : rs.engine;
  if (engine != "slurm") engine = "local";
  if (engine == "slurm" && env_.commands == nullptr) throw std::logic_error("no command runner for Slurm");
  if (engine == "slurm") SlurmSubmission::CheckFolderPath(folder.dir());
  if (todo.empty()) {
    if (env_.out != nullptr) {
      *env_.out << "nothing to resume: every run of " << dir
                << (running > 0 ? " ran to its end or is still running" : " ran to its end") << std::endl;
    }
    return Table(dir);
  }
  const std::unique_ptr<PreparedSweep> prepared = ConfigsToWriteAgain(folder, c, todo, env_.python_runtime_dir);
  std::error_code error;
  auto write_run = [&](size_t index) {
    const std::string& name = c.plan.runs()[index].name;
    if (prepared && !fs::exists(folder.RunDir(name) + "/config.yaml", error)) {
      prepared->WriteRun(folder, index);
    } else {
      folder.ClearRun(name);
    }
  };
  folder.WriteRunScript(env_.dream_path);  // this dream, which may be a newer install
  const std::string started_on = Text(c.settings, "engine");
  const long long started_jobs = Number(c.settings, "jobs");
  spdlog::info("resume: {} of {} runs of {} to run again ({})", todo.size(), c.plan.runs().size(), dir, engine);
  if (engine == "slurm") {
    for (size_t index : todo) write_run(index);
    fs::remove(folder.Path("sweep.csv"), error);
    fs::remove(folder.Path("sweep.md"), error);
    const std::vector<std::string> options =
        rs.slurm_options.empty() ? Strings(c.settings, "slurm_options") : rs.slurm_options;
    const long long minutes = Number(c.settings, "slurm_time_limit_minutes");
    return Submit(
        folder, todo,
        {rs.jobs > 0             ? rs.jobs
         : started_on == "slurm" ? static_cast<int>(started_jobs)
                                 : 0,
         minutes > 0 ? minutes : SlurmSubmission::DefaultTimeLimitMinutes(0), options, env_.dream_path, "dream-sweep"});
  }
  const int jobs = rs.jobs > 0                                 ? rs.jobs
                   : started_on == "local" && started_jobs > 0 ? static_cast<int>(started_jobs)
                                                               : cores();
  const double timeout_s = rs.run_timeout_s > 0 ? rs.run_timeout_s
                           : Number(c.settings, "run_timeout_s") > 0
                               ? static_cast<double>(Number(c.settings, "run_timeout_s"))
                               : 1800.0;
  SweepTable rerun(c.plan.parameter_keys(), todo.size());
  const bool done = RunLocally(folder, c.plan, todo, jobs, timeout_s, write_run, rerun);
  SweepOutcome table = Table(dir);
  table.kind = done ? SweepOutcome::Kind::kFinished : SweepOutcome::Kind::kInterrupted;
  table.runs = todo.size();
  return table;
}

}  // namespace dream::workflows
