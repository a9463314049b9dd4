// dream sweep: one experiment over many seeds and parameter values, one
// `dream run` process per run, as many at once as there are cores, and one
// table of outcomes (docs/sweeps.md).
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#include "command_line.h"
#include "commands.h"
#include "config_override.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/files/output_folder.h"
#include "dream/files/output_folder_lock.h"
#include "dream/run_config/run_config.h"
#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/world/printf_text.h"
#include "parallel_runner.h"
#include "process_group.h"
#include "run_output.h"
#include "seed_list.h"
#include "shared_options.h"
#include "sweep_plan.h"
#include "sweep_run_result.h"
#include "sweep_table.h"

namespace dream::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// A stopped run gets this long to write its log and summary before SIGKILL.
constexpr double kGraceAfterInterruptS = 10.0;

/// A python controller's module named by a relative path, as each run folder
/// keeps a copy of it (as `dream run` keeps one): its text, read when the
/// sweep starts, so a run's config.yaml repeats the run even after the module
/// is edited.
struct ModuleCopy {
  std::string relative_path;  ///< as the config names it
  std::string text;
};

/// The module to copy into each run folder of `root`'s runs; none for other
/// kinds and absolute module paths. While the runs' configs are checked (the
/// run folders do not exist yet), the module is named by its absolute path,
/// resolved from the base config's folder as `dream run` resolves it.
std::optional<ModuleCopy> PythonModuleToCopy(YAML::Node& root, const std::string& base_config_path) {
  YAML::Node controller = root["controller"];
  if (!controller.IsMap() || !controller["kind"].IsScalar() || controller["kind"].Scalar() != "python" ||
      !controller["module"].IsScalar()) {
    return std::nullopt;
  }
  const fs::path module(controller["module"].Scalar());
  if (module.is_absolute()) return std::nullopt;
  const fs::path source = (fs::absolute(base_config_path).parent_path() / module).lexically_normal();
  controller["module"] = source.string();
  if (!fs::is_regular_file(source)) return std::nullopt;  // the check names it
  return ModuleCopy{module.lexically_normal().string(), files::ReadFileText(source.string())};
}

/// What `dream run` checks before it starts (LoadConfig): the run config and
/// the controller section. @throws config::ConfigError.
void CheckRunConfig(const config::ConfigNode& root) {
  const run_config::RunConfig config = run_config::LoadRunConfig(root);
  const agent_host::ControllerFactory factory(config);  // also loads the plugins the config names
}

/// The last line of a run's output that says what went wrong, for the table.
std::string LastErrorLine(const std::string& output_path) {
  std::ifstream in(output_path);
  std::string line;
  std::string last;
  std::string last_error;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    last = line;
    if (line.find("[error]") != std::string::npos || line.rfind("dream:", 0) == 0) last_error = line;
  }
  std::string chosen = last_error.empty() ? last : last_error;
  // Drop spdlog's "[12:00:00.000] [error] " prefix.
  const size_t bracket = chosen.find("] ", chosen.find("] ") + 2);
  if (chosen.rfind("[", 0) == 0 && bracket != std::string::npos) chosen = chosen.substr(bracket + 2);
  return chosen.size() > 160 ? chosen.substr(0, 157) + "..." : chosen;
}

nlohmann::json ReadSummary(const std::string& path) {
  std::ifstream in(path);
  if (!in) return nullptr;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return nullptr;
  }
}

std::string Seconds(double seconds) { return world::PrintfText("%.1f s", seconds); }

/// True when `dir` holds a sweep (its table, or its runs).
bool HoldsSweep(const fs::path& dir) {
  std::error_code error;
  return fs::exists(dir / "sweep.csv", error) || fs::exists(dir / "sweep.md", error) ||
         fs::exists(dir / "runs", error);
}

/// The sweep folder: --out as given (an earlier sweep there is replaced run by
/// run, as documented), else sweeps/<name>, or sweeps/<name>_2, _3, ... when
/// that holds an earlier sweep, so a rerun keeps it. Not created here: bad
/// input must leave no folder behind.
std::string SweepFolder(const SweepArgs& args, const std::string& name) {
  if (!args.out_dir.empty()) return args.out_dir;
  const std::string base = "sweeps/" + name;
  std::string chosen = base;
  for (int n = 2; HoldsSweep(chosen); ++n) chosen = base + "_" + std::to_string(n);
  return chosen;
}

/// The command line that reproduces this sweep (for sweep.md).
std::string ReproducingCommand(const SweepArgs& args, const std::string& seeds, int jobs, const std::string& out_dir) {
  auto quoted = [](const std::string& text) {
    return text.find_first_of(" \t'\"$[]{}*?;&|<>()\\") == std::string::npos ? text : "'" + text + "'";
  };
  std::string line = "dream sweep " + quoted(args.config_path) + " --seeds " + seeds;
  for (const std::string& set : args.sets) line += " --set " + quoted(set);
  line += " --jobs " + std::to_string(jobs);
  if (args.steps > 0) line += " --steps " + std::to_string(args.steps);
  return line + " --out " + quoted(out_dir);
}

}  // namespace

int RunSweep(const SweepArgs& args) {
  // --- everything checked before anything is written or started ---
  const std::string base_text = config::ConfigNode::ReadFile(args.config_path);
  RunArgs base_args;
  base_args.config_path = args.config_path;
  base_args.steps = args.steps;
  const run_config::RunConfig base = LoadConfig(base_args);  // the base config's own mistakes, with its lines

  std::vector<uint64_t> seeds;
  try {
    seeds = args.seeds.empty() ? std::vector<uint64_t>{base.seed} : ParseSeedList(args.seeds);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--seeds " + args.seeds + ": " + e.what());
  }
  std::vector<SweepParameter> parameters;
  for (const std::string& set : args.sets) parameters.push_back(SweepParameter::Parse(set));
  for (const SweepParameter& parameter : parameters) {
    if (parameter.key == "steps" && args.steps > 0) {
      throw std::invalid_argument("--steps and --set steps=... both set the step limit; give one");
    }
  }
  const SweepPlan plan(seeds, parameters);
  const std::vector<SweepPlan::Run>& runs = plan.runs();
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int jobs = args.jobs > 0 ? args.jobs : cores;
  if (args.run_timeout_s <= 0.0) throw std::invalid_argument("--timeout must be > 0");

  const std::string out_dir = SweepFolder(args, base.name);
  const fs::path out(out_dir);
  std::vector<std::string> config_texts;
  std::vector<std::optional<ModuleCopy>> module_copies;
  for (const SweepPlan::Run& run : runs) {
    YAML::Node root = SweepPlan::MakeRunConfig(base_text, args.config_path, run);
    std::optional<ModuleCopy> module_copy = PythonModuleToCopy(root, args.config_path);
    // In the file, not on dream run's command line: the run folder's config alone repeats the run.
    if (args.steps > 0) ApplyConfigOverride(root, "steps", std::to_string(args.steps), args.config_path);
    const std::string where = "run " + run.name + " (" + run.Label() + "): ";
    // Checked in memory against the base file, so an error points at the
    // key's line there; then the file as written, as `dream run` will read it.
    try {
      CheckRunConfig(config::ConfigNode(root, args.config_path, ""));
    } catch (const config::ConfigError& e) {
      throw config::ConfigError(where + e.what());
    }
    const fs::path run_config = out / "runs" / run.name / "config.yaml";
    const std::string header = "Generated by dream sweep from " + args.config_path + ": " + run.Label() +
                               ".\nRun again (replacing this run with the same one): dream run " +
                               run_config.string() + " --out " + (out / "runs" / run.name).string() + " --overwrite";
    const std::string text = SweepPlan::EmitConfig(root, header);
    try {
      CheckRunConfig(config::ConfigNode::LoadString(text, run_config.string()));
    } catch (const config::ConfigError& e) {
      throw config::ConfigError(where + "the generated config: " + e.what());
    }
    if (module_copy) {
      // Written with the module's own relative path: the run folder's copy.
      root["controller"]["module"] = module_copy->relative_path;
      config_texts.push_back(SweepPlan::EmitConfig(root, header));
    } else {
      config_texts.push_back(text);
    }
    module_copies.push_back(std::move(module_copy));
  }
  // Created if missing; a given --out's parent must exist, as for every --out.
  files::OutputFolder(out_dir, args.out_dir.empty() ? files::OutputFolder::Parents::kCreate
                                                  : files::OutputFolder::Parents::kMustExist)
      .MakeSubfolder("runs");
  files::OutputFolderLock::HoldUntilExit(out_dir);  // a second sweep into it is refused while this one runs
  if (args.out_dir.empty() && out_dir != "sweeps/" + base.name) {
    spdlog::warn("sweeps/{} holds an earlier sweep, so this one goes to {} (--out DIR to choose)", base.name, out_dir);
  }

  // --- the runs, `jobs` at a time ---
  const std::string self = SelfExecutable();
  const bool progress = spdlog::default_logger()->should_log(spdlog::level::info);
  spdlog::info(
      "sweep: {} runs of {} ({} seeds{}), {} at a time on {} cores -> {}", runs.size(), base.name, seeds.size(),
      parameters.empty() ? std::string() : " x " + std::to_string(runs.size() / seeds.size()) + " parameter sets", jobs,
      cores, out_dir);
  SweepTable table(plan.parameter_keys(), runs.size());
  size_t finished = 0;
  const Clock::time_point sweep_started = Clock::now();

  auto prepare = [&](size_t index) {
    const fs::path run_dir = out / "runs" / runs[index].name;
    std::error_code error;
    fs::create_directory(run_dir, error);
    // A folder left by an earlier sweep: its outputs must not pass for this run's.
    for (const char* stale : {"summary.json", "run.lcmlog", "trajectories.png", "output.txt"}) {
      fs::remove(run_dir / stale, error);
    }
    files::WriteFileAtomically((run_dir / "config.yaml").string(), config_texts[index]);
    if (const std::optional<ModuleCopy>& module = module_copies[index]) {
      files::OutputFolder(run_dir.string()).WriteFileInSubfolders(module->relative_path, module->text);
    }
    return ParallelRunner::Job{{self, "run", (run_dir / "config.yaml").string(), "--out", run_dir.string()},
                               (run_dir / "output.txt").string()};
  };
  auto on_finished = [&](const ParallelRunner::Finished& done) {
    const SweepPlan::Run& run = runs[done.index];
    const fs::path run_dir = out / "runs" / run.name;
    if (done.timed_out)
      spdlog::warn("{}: still running after {:.0f} s (--timeout); stopped", run.Label(), args.run_timeout_s);
    const bool failed = done.exit_code != 0 && done.exit_code != 3 && done.exit_code != 130;
    const std::string hint = !done.start_error.empty() ? "could not start: " + done.start_error
                             : failed                  ? LastErrorLine((run_dir / "output.txt").string())
                                                       : std::string();
    SweepRunResult result = SweepRunResult::Judge(run, done.exit_code, done.timed_out, done.wall_time_s,
                                                  ReadSummary((run_dir / "summary.json").string()), hint);
    ++finished;
    if (progress) {
      std::string line = "[" + std::to_string(finished) + "/" + std::to_string(runs.size()) + "] " + run.Label() +
                         ": " + result.OutcomeText();
      if (result.status == SweepRunResult::Status::kRan) line += ", " + std::to_string(result.steps) + " steps";
      std::cout << line << std::endl;
    }
    table.Add(std::move(result));
  };
  ParallelRunner runner(jobs, args.run_timeout_s, kGraceAfterInterruptS);
  const bool stopping = !runner.Run(runs.size(), StopFlag(), prepare, on_finished);
  if (stopping) spdlog::warn("sweep interrupted: {} of {} runs ended, the rest never started", finished, runs.size());
  const double wall_s = std::chrono::duration<double>(Clock::now() - sweep_started).count();

  // --- the table, also for an interrupted sweep (the runs that ended) ---
  const std::string seeds_text = args.seeds.empty() ? std::to_string(base.seed) : args.seeds;
  const std::vector<std::pair<std::string, std::string>> facts = {
      {"command", ReproducingCommand(args, seeds_text, jobs, out_dir)},
      {"runs in parallel", std::to_string(jobs) + " (" + std::to_string(cores) + " cores)"},
      {"wall time", Seconds(wall_s) + (stopping ? " (interrupted)" : "")},
  };
  const std::string csv_path = (out / "sweep.csv").string();
  const std::string md_path = (out / "sweep.md").string();
  files::WriteFileAtomically(csv_path, table.Csv());
  files::WriteFileAtomically(md_path, table.Markdown("Sweep of " + base.name + " (" + args.config_path + ")", facts));
  std::cout << "\n" << table.SummaryMarkdown(facts) << "\ntable: " << md_path << "\ncsv:   " << csv_path << "\n";

  if (stopping) return kExitInterrupted;
  const SweepSummary summary = table.Summary();
  if (summary.failed > 0) {
    spdlog::error("{} of {} runs failed to run (see the problem column of {})", summary.failed, runs.size(), md_path);
    return kExitRunFailed;
  }
  return kExitOk;
}

void DeclareSweepCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<SweepArgs>(
      "sweep",
      "Run an experiment over many seeds and parameter values in parallel (one dream run process per\n"
      "run, --jobs at a time) and tabulate the outcomes in <out>/sweep.csv and sweep.md (docs/sweeps.md).\n"
      "Example: dream sweep config/hrvo_circle.yaml --seeds 1-20   (writes sweeps/hrvo_circle)",
      RunSweep);
  command->add_option("config", args->config_path, "Run config (YAML) to sweep")->required();
  command->add_option("--seeds", args->seeds, "Seeds: 7, 1-20 or 1,4,9-12 (default: the config's seed)");
  command
      ->add_option("--set", args->sets,
                   "KEY=V1,V2,...: also sweep this config key (dotted: controller.max_speed_mps,\n"
                   "controller.sensors.0.noise_std); repeat for more keys, every combination runs")
      ->allow_extra_args(false);
  command->add_option("-j,--jobs", args->jobs, "Runs at once (default: one per core)")->check(CLI::Range(1, 1024));
  command->add_option("--steps", args->steps, "Override the config's step limit in every run")->check(StepCount());
  command->add_option("--out", args->out_dir,
                      "Sweep folder (its parent must exist; default sweeps/<name>, or sweeps/<name>_2, ...\n"
                      "when that holds an earlier sweep)");
  command->add_option("--timeout", args->run_timeout_s,
                      "Stop a run still going after this many seconds; it counts as failed")
      ->check(Seconds(false))
      ->capture_default_str();
}

}  // namespace dream::cli
