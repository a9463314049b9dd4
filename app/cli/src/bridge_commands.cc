// dream export / import / lab-replay / compare / check-submission: the bridge
// to the Robotarium (docs/robotarium.md). The work is in dream::workflows;
// this file is options, messages and exit codes.
#include <spdlog/spdlog.h>

#include <csignal>
#include <cstdlib>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "dream/files/run_folder_choice.h"
#include "dream/process/data_files.h"
#include "dream/process/process_group.h"
#include "dream/workflows/check_submission.h"
#include "dream/workflows/compare_workflow.h"
#include "dream/workflows/export_workflow.h"
#include "dream/workflows/import_workflow.h"
#include "dream/workflows/lab_replay_workflow.h"
#include "dream/workflows/script_export.h"
#include "dream/files/file_text.h"
#include "script_command.h"
#include "shared_options.h"
#include <unistd.h>
#include <filesystem>

#ifndef DREAM_DEFAULT_PYTHON
#define DREAM_DEFAULT_PYTHON "/usr/bin/python3"
#endif

namespace dream::cli {
namespace {

struct CheckSubmissionArgs {
  workflows::CheckSubmission::Options options;  ///< as typed; RunCheckSubmission adds the runner and runtime
  std::string python;                           ///< empty: the configured Python (/usr/bin/python3)
};

/// What the workflows that run or judge a run take from this program: the
/// Python runtime beside it (a Python controller's metrics and goal) and the
/// stop flag Ctrl-C sets.
template <typename Options>
Options WithRuntime(Options options) {
  options.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  options.stop = &StopFlag();
  return options;
}

/// `dream export SCRIPT.py` (or the folder of a script's run): the script is the upload.
int RunScriptExport(const workflows::ExportWorkflow::Asked& asked, const std::string& script) {
  if (asked.calibration || !asked.strategy.empty() || asked.barriers || !asked.config_path.empty()) {
    throw std::invalid_argument("dream export " + asked.run_dir +
                                ": a Robotarium script is uploaded as it is: --calibration, --strategy, --barriers "
                                "and --config are for runs of DREAM's controllers");
  }
  workflows::ScriptExport::Options options;
  options.script_path = script;
  options.out_dir = asked.out_dir;
  options.python = DREAM_DEFAULT_PYTHON;
  options.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  const char* simulator = std::getenv("ROBOTARIUM_PYTHON_SIMULATOR");
  std::error_code error;
  if (simulator != nullptr && *simulator != '\0' &&
      std::filesystem::is_regular_file(std::filesystem::path(simulator) / "libraries.txt", error)) {
    options.libraries_path = (std::filesystem::path(simulator) / "libraries.txt").string();
  }
  const auto run_checker = [](const std::vector<std::string>& argv) {
    const std::string output =
        (std::filesystem::temp_directory_path() / ("dream-export-imports-" + std::to_string(::getpid()) + ".txt"))
            .string();
    process::ProcessGroup group;
    workflows::ScriptExport::Checked checked;
    checked.exit_code = group.Wait(group.Start(argv, output));
    checked.output = files::ReadFileText(output, 1 << 20);
    std::error_code ignored;
    std::filesystem::remove(output, ignored);
    return checked;
  };
  const workflows::ScriptExport::Result result = workflows::ScriptExport().Export(options, run_checker);
  if (result.refused) {
    std::cerr << "dream export: " << result.refusal << "\nnothing was written.\n";
    return kExitRejected;
  }
  std::string imports;
  for (const std::string& name : result.imports) imports += (imports.empty() ? "" : ", ") + name;
  std::cout << "exported " << script << " as it is: upload " << result.out_dir << "/upload/" << result.script_file
            << " and " << result.out_dir << "/upload/" << result.main_file << " (main file " << result.main_file
            << ": DREAM's recorder, which runs the script and saves dream_result.npy); it imports "
            << (imports.empty() ? std::string("nothing") : imports)
            << ", all on the Robotarium\ncheck it in the Robotarium simulator: dream check-submission "
            << result.out_dir << "\nthe lab's dream_result.npy: dream import dream_result.npy --export "
            << result.out_dir << "\n";
  return kExitOk;
}

int RunExport(const workflows::ExportWorkflow::Asked& asked) {
  if (IsScriptPath(asked.run_dir)) return RunScriptExport(asked, asked.run_dir);
  if (const std::string script = ScriptOfConfig(asked.run_dir + "/config.yaml"); !script.empty()) {
    return RunScriptExport(asked, script);
  }
  std::string refusal;
  const int code = workflows::ExportWorkflow().ExportAsAsked(WithRuntime(asked), &refusal);
  if (!refusal.empty()) std::cerr << "dream export: " << refusal << "\nnothing was written.\n";
  return code;
}

int RunImport(workflows::ImportWorkflow::Asked asked) {
  asked.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  const workflows::ImportWorkflow::Options options = workflows::ImportWorkflow::OptionsOf(asked);
  const workflows::ImportWorkflow importer;
  const workflows::ImportWorkflow::Result imported = importer.Import(options);
  importer.PrintVerdict(imported);
  return workflows::ImportWorkflow::ExitCodeOf(imported);
}

int RunCompare(workflows::CompareWorkflow::Options options) {
  options.python_runtime_dir = process::DataFiles::PythonRuntimeDir();
  workflows::CompareWorkflow().Compare(options);
  return kExitOk;
}

int RunLabReplay(const workflows::LabReplayWorkflow::Options& options) {
  // A script's lab run: the script runs again as the agent of every robot.
  if (!ScriptOfConfig((std::filesystem::path(options.lab_dir) / "config.yaml").string()).empty() &&
      !options.world_only) {
    return RunScriptLabReplay(WithRuntime(options));
  }
  return workflows::LabReplayWorkflow().Replay(WithRuntime(options)).exit_code;
}

/// What check-submission starts: the runner in its own process group
/// (Ctrl-C passed on); its lab replay is the workflow's own (in this process).
workflows::CheckSubmission::Tools CheckSubmissionTools() {
  workflows::CheckSubmission::Tools tools;
  tools.run_script = [](const std::vector<std::string>& argv) {
    workflows::CheckSubmission::ScriptRun ran;
    process::ProcessGroup group;
    const pid_t pid = group.Start(argv);
    ran.exit_code = group.WaitPassingOnStop(pid, StopFlag(), SIGINT);
    ran.interrupted = StopFlag().load();
    return ran;
  };
  tools.choose_folder = [](const std::string& out, const std::string& default_dir, bool overwrite) {
    return files::RunFolderChoice(out, default_dir, overwrite).dir();
  };
  return tools;
}

int RunCheckSubmission(const CheckSubmissionArgs& args) {
  workflows::CheckSubmission::Options options = WithRuntime(args.options);
  if (const char* env = std::getenv("ROBOTARIUM_PYTHON_SIMULATOR")) options.simulator_from_environment = env;
  options.python = args.python.empty() ? DREAM_DEFAULT_PYTHON : args.python;
  options.runner_script = process::DataFiles::BridgePythonDir() + "/run_submission.py";
  const workflows::CheckSubmission::Result result = workflows::CheckSubmission(options, CheckSubmissionTools()).Run();
  using Outcome = workflows::CheckSubmission::Outcome;
  if (!result.error.empty()) std::cerr << "dream check-submission: " << result.error << "\n";
  switch (result.outcome) {
    case Outcome::kPassed:
      return kExitOk;
    case Outcome::kNotReady:
    case Outcome::kControllersDiffer:
      return kExitNotReady;
    case Outcome::kRejected:
    case Outcome::kStartupTimedOut:
      return kExitRejected;
    case Outcome::kNoOfficialSimulator:
      return kExitInputError;
    case Outcome::kInterrupted:
      return kExitInterrupted;
    case Outcome::kIncomplete:
    case Outcome::kScriptFailed:
    case Outcome::kRunnerFailed:
      break;
  }
  return kExitRunFailed;
}

void DeclareExportCommand(CommandLine& line) {
  const auto [export_command, export_args] = line.AddCommand<workflows::ExportWorkflow::Asked>(
      "export",
      "Turn a recorded run into a Robotarium submission (a main script plus .npy data, and for\n"
      "--strategy controller the Python controller and DREAM's runtime), after checking it as the\n"
      "lab would: robots, duration, start poses, boundary and collision errors.\n"
      "With --calibration --robots N it first runs the calibration drive on N robots (the run behind\n"
      "dream calibrate) and exports that: one upload gives your lab's model.\n"
      "Example: dream export runs/go_to_goal --out exports/go_to_goal\n"
      "         dream export --calibration --robots 8",
      RunExport);
  export_command->add_option("run", export_args->run_dir,
                             "Run folder written by dream run (run.lcmlog, config.yaml), or a Robotarium script\n"
                             "(SCRIPT.py: uploaded as it is, docs/robotarium-scripts.md); with --calibration,\n"
                             "the folder its run goes into (default runs/calibration_N)");
  export_command->add_option("--out", export_args->out_dir, "Output folder (default exports/<name>)");
  export_command->add_option("--config", export_args->config_path, "The run's config (default <run>/config.yaml)");
  export_command
      ->add_option("--strategy", export_args->strategy,
                   "track: recorded commands plus feedback on the pose error; replay: open loop;\n"
                   "controller: the run's Python controller itself, every step on the lab's poses\n"
                   "(default track; --calibration: replay)")
      ->check(CLI::IsMember(workflows::ExportWorkflow::StrategyNames()));
  export_command->add_flag("--calibration", export_args->calibration,
                           "Run the calibration drive (config/calibration.yaml's program) on --robots robots in the\n"
                           "ideal simulator, then export it open loop (replay); the lab's result, imported, is what\n"
                           "dream calibrate fits (docs/robotarium.md)");
  export_command->add_option("--robots", export_args->robots, "With --calibration: how many robots, 1 to 20");
  export_command->add_flag(
      "--force", export_args->force,
      "Export although the run is not ready: robots lost at its end (a controller failed or an\n"
      "agent fell silent) or its experiment's goal missed; those problems are printed as warnings");
  export_command->add_flag("--barriers", export_args->barriers,
                           "Pass commands through the Robotarium's barrier certificates (safety layer)");
  export_command
      ->add_option("--settle-steps", export_args->settle_steps,
                   "At most this many steps to settle on the start poses before step 0")
      ->check(CLI::Range(0, 3000))
      ->capture_default_str();
}

void DeclareImportCommand(CommandLine& line) {
  const auto [import_command, import_args] = line.AddCommand<workflows::ImportWorkflow::Asked>(
      "import",
      "Turn what the lab returned (dream_result.npy, or dream_result.mat from MATLAB) into a run\n"
      "folder like dream run writes: run.lcmlog, summary.json, trajectories.png. Its verdict holds the\n"
      "run to the lab verifier's rules against what UPLOAD.txt said to declare (robot count, duration),\n"
      "or what --declared-robots / --declared-duration say was declared, and, as dream run's, to the\n"
      "experiment's goal.\n"
      "Example: dream import ~/Downloads/dream_result.npy --export exports/go_to_goal --out runs/lab1",
      RunImport);
  import_command->add_option("result", import_args->result, "dream_result.npy / .mat, or a folder holding one")
      ->required();
  import_command->add_option("--export", import_args->export_dir, "The folder dream export wrote")->required();
  AddRunFolderOptions(import_command, &import_args->out_dir, &import_args->overwrite, "runs/<name>_lab");
  import_command
      ->add_option("--declared-robots", import_args->declared_robots,
                   "The robot count declared on the lab's form, when not UPLOAD.txt's;\n"
                   "the verdict names a mismatch (verifier_robot_count)")
      ->check(CLI::Range(1, 1000));
  import_command
      ->add_option("--declared-duration", import_args->declared_duration_s,
                   "The duration (s) declared on the lab's form, when not UPLOAD.txt's; the verdict\n"
                   "names a run over 1.5x of it (verifier_duration) or over 900 s (lab_duration_cap)")
      ->check(CLI::Range(0.001, 1e6));
}

void DeclareLabReplayCommand(CommandLine& line) {
  const auto [replay_command, replay_args] = line.AddCommand<workflows::LabReplayWorkflow::Options>(
      "lab-replay",
      "Run a lab run (from dream import) as the world on the bus: the agents get the lab's poses\n"
      "and their commands are recorded beside the lab's. Agents run in this process (memq://)\n"
      "unless --world-only.\n"
      "Example: dream lab-replay runs/lab1 --out runs/lab1_replay",
      RunLabReplay);
  replay_command->add_option("lab", replay_args->lab_dir, "Run folder written by dream import")->required();
  AddRunFolderOptions(replay_command, &replay_args->out_dir, &replay_args->overwrite, "runs/<name>_lab_replay");
  replay_command->add_option("--lcm-url", replay_args->lcm_url,
                             "LCM URL (default memq://, or $LCM_DEFAULT_URL with --world-only)");
  replay_command->add_option("--steps", replay_args->steps, "Replay at most this many steps")->check(StepCount());
  replay_command->add_option("--mode", replay_args->mode, "Override the world mode")
      ->check(CLI::IsMember({"lockstep", "realtime"}));
  replay_command->add_flag("--world-only", replay_args->world_only,
                           "Only the world; start the agents elsewhere (dream agent CONFIG) on the same URL");
}

void DeclareCompareCommand(CommandLine& line) {
  const auto [compare_command, compare_args] = line.AddCommand<workflows::CompareWorkflow::Options>(
      "compare",
      "Compare a simulated run with its lab run: tracking error per robot, closest approach,\n"
      "violations and the experiment's metrics side by side; writes comparison.json and .png.\n"
      "Example: dream compare runs/go_to_goal runs/lab1",
      RunCompare);
  compare_command->add_option("simulated", compare_args->first_dir, "The simulated run's folder")->required();
  compare_command->add_option("lab", compare_args->second_dir, "The lab run's folder (dream import)")->required();
  compare_command->add_option("--out", compare_args->out_dir, "Output folder (default: the lab run's folder)");
}

void DeclareCheckSubmissionCommand(CommandLine& line) {
  const auto [check_command, check_args] = line.AddCommand<CheckSubmissionArgs>(
      "check-submission",
      "Run an exported submission in the official Robotarium Python simulator (or, when it is\n"
      "not installed, DREAM's stand-in), import what it saved and compare it with the run.\n"
      "Example: dream check-submission exports/go_to_goal --out runs/go_to_goal_check",
      RunCheckSubmission);
  check_command->add_option("export", check_args->options.export_dir, "The folder dream export wrote")->required();
  AddRunFolderOptions(check_command, &check_args->options.out_dir, &check_args->options.overwrite, "runs/<name>_check");
  check_command->add_option("--run", check_args->options.run_dir,
                            "The simulated run to compare with (default: the exported one)");
  check_command->add_option("--simulator", check_args->options.simulator,
                            "robotarium_python_simulator checkout (default $ROBOTARIUM_PYTHON_SIMULATOR)");
  check_command->add_option("--python", check_args->python, "Python with numpy (and what the simulator needs)");
  check_command->add_flag("--standin", check_args->options.standin,
                          "Use DREAM's stand-in even if the official one is there");
  check_command->add_flag("--require-official", check_args->options.require_official,
                          "Fail (exit 1) instead of using the stand-in when the official simulator is missing");
  check_command->add_flag("--skip-initialization", check_args->options.skip_initialization,
                          "Start exactly at the start poses (no start-up drive)");
}

}  // namespace

void DeclareBridgeCommands(CommandLine& line) {
  DeclareExportCommand(line);
  DeclareImportCommand(line);
  DeclareLabReplayCommand(line);
  DeclareCompareCommand(line);
  DeclareCheckSubmissionCommand(line);
}

}  // namespace dream::cli
