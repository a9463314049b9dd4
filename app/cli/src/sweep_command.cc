// dream sweep: one experiment over many seeds and parameter values, one
// `dream run` per run, on this machine's cores, a Slurm job array or planned
// for another scheduler, and one table of outcomes (docs/sweeps.md). The
// workflow is workflows::SweepWorkflow; this file parses options and maps
// outcomes to exit codes.
#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>

#include "command_line.h"
#include "commands.h"
#include "dream/workflows/sweep_workflow.h"
#include "parallel_runner.h"
#include "process_command_runner.h"
#include "dream/process/process_group.h"
#include "dream/process/data_files.h"
#include "dream/workflows/run_workflow.h"
#include "dream/workflows/script_run_workflow.h"
#include "shared_options.h"

namespace dream::cli {
namespace {

/// A stopped run gets this long to write its log and summary before SIGKILL.
constexpr double kGraceAfterInterruptS = 10.0;

/// `dream sweep resume|status|table DIR`'s options.
struct SweepFolderArgs {
  std::string dir;
  std::string engine;  ///< resume: empty keeps the sweep's
  int jobs = 0;
  double run_timeout_s = 0.0;
  std::vector<std::string> slurm_options;
};

/// The workflow with this process's children, Slurm's commands and Ctrl-C.
workflows::SweepWorkflow Workflow(ProcessCommandRunner& commands) {
  workflows::SweepWorkflow::Environment env;
  env.make_job_runner = [](int jobs, double run_timeout_s) -> std::unique_ptr<workflows::JobRunner> {
    return std::make_unique<ParallelRunner>(jobs, run_timeout_s, kGraceAfterInterruptS);
  };
  env.commands = &commands;
  env.stop = &StopFlag();
  env.out = &std::cout;
  env.progress = spdlog::default_logger()->should_log(spdlog::level::info);
  env.dream_path = process::SelfExecutable();
  env.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  return workflows::SweepWorkflow(std::move(env));
}

/// The exit code of a sweep that ran here (or a table written).
int ExitCodeOf(const workflows::SweepOutcome& outcome) {
  using Kind = workflows::SweepOutcome::Kind;
  if (outcome.kind == Kind::kInterrupted) return kExitInterrupted;
  if (outcome.kind != Kind::kFinished) return kExitOk;  // submitted or planned
  const workflows::SweepSummary& s = outcome.summary;
  if (s.failed > 0) {
    spdlog::error("{} of {} runs failed to run (see the problem column of {}/sweep.md)", s.failed, s.planned,
                  outcome.out_dir);
    return kExitRunFailed;
  }
  if (s.not_run > 0 || s.interrupted > 0) {
    spdlog::warn("{} of {} runs have no result yet (dream sweep status {})", s.not_run + s.interrupted, s.planned,
                 outcome.out_dir);
    return kExitRunFailed;
  }
  return kExitOk;
}

int RunSweepResume(const SweepFolderArgs& args) {
  ProcessCommandRunner commands;
  if (!args.engine.empty()) workflows::SweepSettings::ParseEngine(args.engine);  // names the choices
  if (args.engine == "plan") throw std::invalid_argument("--engine plan: resume runs the runs; use local or slurm");
  return ExitCodeOf(
      Workflow(commands).Resume(args.dir, {args.engine, args.jobs, args.run_timeout_s, args.slurm_options}));
}

int RunSweepTable(const SweepFolderArgs& args) {
  ProcessCommandRunner commands;
  return ExitCodeOf(Workflow(commands).Table(args.dir));
}

int RunSweepStatus(const SweepFolderArgs& args) {
  ProcessCommandRunner commands;
  std::cout << Workflow(commands).Status(args.dir).Text();
  return kExitOk;
}

void DeclareSweepFolderCommands(CommandLine& line, CLI::App* sweep) {
  // Each command works on one sweep folder, its one positional argument.
  auto folder_command = [&line, sweep](const char* name, const char* help, int (*run)(const SweepFolderArgs&)) {
    auto command = line.AddCommand<SweepFolderArgs>(name, help, std::function<int(const SweepFolderArgs&)>(run), sweep);
    command.app->add_option("dir", command.args->dir, "The sweep folder")->required();
    return command;
  };
  folder_command("status",
                 "How far a sweep is: runs finished, running, pending, failed and never started, from its folder\n"
                 "and Slurm (squeue, sacct). Example: dream sweep status sweeps/hrvo_circle",
                 RunSweepStatus);
  folder_command(
      "table",
      "Write sweep.csv and sweep.md from whatever runs of a sweep have finished, at any time; runs that\n"
      "failed, were cancelled or never started are rows saying so. Example: dream sweep table sweeps/hrvo_circle",
      RunSweepTable);
  const auto [resume, resume_args] =
      folder_command("resume",
                     "Run again every run of a sweep without a complete result (failed, cancelled, timed out,\n"
                     "interrupted, never started), locally or on Slurm. Example: dream sweep resume sweeps/hrvo_circle",
                     RunSweepResume);
  resume->add_option("--engine", resume_args->engine, "local or slurm (default: the sweep's own; plan: local)");
  resume->add_option("-j,--jobs", resume_args->jobs, "Runs at once (default: the sweep's)")
      ->check(CLI::Range(1, 100000));
  resume->add_option("--timeout", resume_args->run_timeout_s, "Local engine: stop a run after this many seconds")
      ->check(Seconds(false));
  resume
      ->add_option("--slurm-option", resume_args->slurm_options,
                   "An sbatch option for the jobs, e.g. --slurm-option=--partition=short (default: the sweep's)")
      ->allow_extra_args(false);
}

}  // namespace

int RunSweep(const SweepArgs& args) {
  // --- everything checked before anything is written or started ---
  workflows::SweepSettings settings;
  settings.engine = workflows::SweepSettings::ParseEngine(args.engine);
  RunArgs base_args;
  base_args.config_path = args.config_path;
  base_args.steps = args.steps;
  // The base config's own mistakes, with its lines (a script's: the config its runs start from).
  const std::string python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  const auto base = workflows::ScriptRunWorkflow::IsScript(args.config_path)
                        ? workflows::ScriptRunWorkflow::BaseConfig(args.config_path, python_runtime_dir)
                        : workflows::RunWorkflow(python_runtime_dir, StopFlag()).LoadConfig(base_args);
  settings.python_runtime_dir = python_runtime_dir;
  settings.config_path = args.config_path;
  settings.seeds = args.seeds;
  settings.sets = args.sets;
  settings.zips = args.zips;
  settings.jobs = args.jobs;
  settings.steps = args.steps;
  settings.out_dir = args.out_dir;
  settings.run_timeout_s = args.run_timeout_s;
  settings.slurm_options = args.slurm_options;
  ProcessCommandRunner commands;
  return ExitCodeOf(Workflow(commands).Start(settings, base));
}

void DeclareSweepCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<SweepArgs>(
      "sweep",
      "Run an experiment over many seeds and parameter values (one dream run per run) on this machine's\n"
      "cores (--jobs at a time), a Slurm cluster (--engine slurm) or another scheduler (--engine plan), and\n"
      "tabulate the outcomes per run and per value in <out>/sweep.csv and sweep.md (docs/sweeps.md).\n"
      "Example: dream sweep config/hrvo_circle.yaml --seeds 1-20   (writes sweeps/hrvo_circle)\n"
      "Then: dream sweep status|resume|table DIR",
      RunSweep);
  command->add_option("config", args->config_path,
                      "Run config (YAML) to sweep, or a Robotarium script (a .py file: docs/robotarium-scripts.md)");
  command->add_option("--seeds", args->seeds, "Seeds: 7, 1-20 or 1,4,9-12 (default: the config's seed)");
  command
      ->add_option("--set", args->sets,
                   "KEY=V1,V2,...: also sweep this config key (dotted: controller.max_speed_mps,\n"
                   "controller.sensors.0.noise_std); repeat for more keys, every combination runs")
      ->allow_extra_args(false)
      ->check(KeyValue());
  command
      ->add_option("--zip", args->zips,
                   "KEY=V1,V2,...: vary this key together with the other --zip keys (the first values in one\n"
                   "run, the second in the next, ...; each --zip lists as many values), in every combination\n"
                   "with the --set keys. Example: --zip controller.max_speed_mps=0.1,0.2\n"
                   "--zip controller.sensors.0.range_m=0.5,1.0")
      ->allow_extra_args(false)
      ->check(KeyValue());
  command->add_option("-j,--jobs", args->jobs, "Runs at once (default: one per core; Slurm: no limit)")
      ->check(CLI::Range(1, 100000));
  command->add_option("--steps", args->steps, "Override the config's step limit in every run")->check(StepCount());
  command->add_option("--out", args->out_dir,
                      "Sweep folder (its parent must exist; default sweeps/<name>, or sweeps/<name>_2, ...\n"
                      "when that holds an earlier sweep); for Slurm on a file system the nodes share");
  command
      ->add_option("--timeout", args->run_timeout_s,
                   "Stop a run still going after this many seconds; it counts as failed (local engine)")
      ->check(Seconds(false))
      ->capture_default_str();
  command
      ->add_option("--engine", args->engine,
                   "local (this machine), slurm (a job array: sbatch), or plan (write <out>/commands.txt,\n"
                   "one shell command per run, and stop)")
      ->capture_default_str();
  command
      ->add_option("--slurm-option", args->slurm_options,
                   "An sbatch option for the jobs, passed on as it is: --slurm-option=--partition=short,\n"
                   "--slurm-option=--time=30 (default time: 10 min + 0.1 s per step); repeat for more")
      ->allow_extra_args(false);
  DeclareSweepFolderCommands(line, command);
  // CONFIG is needed unless a subcommand (status, resume, table) was given.
  command->parse_complete_callback([command = command, args = args] {
    if (args->config_path.empty() && command->get_subcommands().empty()) throw CLI::RequiredError("config");
  });
}

}  // namespace dream::cli
