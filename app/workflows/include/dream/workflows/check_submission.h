#pragma once

#include <atomic>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "dream/workflows/import_workflow.h"
#include "dream/workflows/script_export.h"
#include "dream/bridge/command_agreement.h"
#include "dream/bridge/lab_import.h"
#include "dream/files/output_folder.h"

namespace dream::workflows {

/// `dream check-submission`: runs an exported submission in the official
/// Robotarium Python simulator (or DREAM's stand-in) with the bridge's runner
/// script, imports what it saved (ImportWorkflow), compares it with the
/// simulated run and, for the controller strategy, replays the lab's poses
/// against the same controllers; writes check.json. What starts processes
/// (the runner, the replay's agents) and chooses the output folder is given
/// as Tools, so a test can give fakes.
class CheckSubmission {
 public:
  struct Options {
    std::string export_dir;  ///< the folder dream export wrote
    std::string out_dir;     ///< --out; empty: runs/<name>_check (Tools::choose_folder decides)
    bool overwrite = false;
    std::string run_dir;    ///< the simulated run to compare with; empty: the exported one
    std::string simulator;  ///< --simulator: a robotarium_python_simulator checkout
    /// $ROBOTARIUM_PYTHON_SIMULATOR (the caller reads the environment), used without --simulator.
    std::string simulator_from_environment;
    std::string python;         ///< the Python the runner runs with
    std::string runner_script;  ///< bridge/python/run_submission.py
    bool standin = false;
    bool require_official = false;
    bool skip_initialization = false;
    /// DREAM's Python package (python/): a Python controller's own goal and metrics
    /// (goal_points, metrics, goal) in the import's summary.json and the comparison;
    /// empty: the built-in kinds' only.
    std::string python_runtime_dir;
    /// Ends the check's own lab replay early when set (Ctrl-C); none: it ends by itself.
    const std::atomic<bool>* stop = nullptr;
  };

  /// How a process the check started ended.
  struct ScriptRun {
    int exit_code = 0;
    bool interrupted = false;  ///< Ctrl-C stopped it
  };
  /// What a lab replay (dream lab-replay) of the imported run gave.
  struct Replay {
    bool interrupted = false;
    std::optional<bridge::CommandAgreement> agreement;  ///< none: it ended before its first step
  };
  struct Tools {
    /// Runs the runner (argv[0] the Python) to its end.
    std::function<ScriptRun(const std::vector<std::string>& argv)> run_script;
    /// Replays the run folder `lab_dir` into `replay_dir` (replacing it) with
    /// the config's controllers as agents. @throws std::exception when it cannot.
    /// None: LabReplayWorkflow in this process, quietly (its verdict would
    /// repeat the check's).
    std::function<Replay(const std::string& lab_dir, const std::string& replay_dir)> replay_lab;
    /// The output folder, made and locked: (--out, the default, --overwrite).
    /// @throws std::runtime_error when it holds a run and overwrite is off.
    std::function<std::string(const std::string& out, const std::string& default_dir, bool overwrite)> choose_folder;
  };

  enum class Outcome {
    kPassed,               ///< the script ran to its end and the lab run was imported
    kNotReady,             ///< the imported run's verdict is not_ready (its goal missed, ...), as dream import says
    kControllersDiffer,    ///< the controllers decided differently on the lab's poses (not ready)
    kIncomplete,           ///< the script stopped before its last step
    kRejected,             ///< debug() rejected the run
    kStartupTimedOut,      ///< the script did not start in the lab's time (rejected)
    kScriptFailed,         ///< the script raised in the simulator
    kRunnerFailed,         ///< the runner ended before writing its report
    kNoOfficialSimulator,  ///< --require-official and none was found
    kInterrupted,
  };
  struct Result {
    Outcome outcome = Outcome::kPassed;
    std::string error;             ///< for kScriptFailed .. kInterrupted: what to print on stderr
    nlohmann::ordered_json check;  ///< check.json (empty when not written)
    std::string dir;               ///< the check's folder ("" when none was made)
  };

  CheckSubmission(Options options, Tools tools, std::ostream& out = std::cout);
  // Its default replay_lab refers to this object's options.
  CheckSubmission(const CheckSubmission&) = delete;
  CheckSubmission& operator=(const CheckSubmission&) = delete;

  /// A script's export (ScriptExport::Read) runs the script alone: check.json
  /// holds the simulator's debug() verdict and text.
  /// @throws std::runtime_error naming the file or option: an upload edited
  ///         after the export, a simulator folder that is no checkout, --out
  ///         being the compared run, an output folder holding a run.
  Result Run() const;

  /// The runner's report (check_report.json) name in the check's folder.
  static constexpr const char* kReportName = "check_report.json";

 private:
  std::string SimulatorChecked() const;
  /// `main_file` non-empty: a script's export (ScriptExport), run as its main file, unpaced.
  std::vector<std::string> RunnerArgv(const std::string& workdir, const std::string& report_path,
                                      const std::string& main_file = "") const;
  /// The check of a Robotarium script's export (ScriptExport): the script in
  /// the simulator, its debug() verdict; nothing to import or compare.
  Result RunScriptCheck(const ScriptExport::Manifest& manifest) const;
  std::optional<Result> RunRunner(const files::OutputFolder& out, const std::string& workdir, nlohmann::json* report,
                                  const std::string& main_file = "") const;
  void CompareWithRun(const std::string& run_dir, const std::string& dir, nlohmann::ordered_json* check) const;
  void PrintDebugReport(const nlohmann::json& report, const std::vector<std::string>& warnings) const;
  /// The lab's result imported into `out_dir` (dream import's run), its verdict and goal printed.
  ImportWorkflow::Result ImportLabRun(const std::string& out_dir, const std::string& workdir) const;
  nlohmann::ordered_json ControllersOnLabPoses(const files::OutputFolder& out, Replay* replayed) const;
  void PrintAgreement(const bridge::CommandAgreement& agreement, const std::string& replay_dir) const;

  Options options_;
  Tools tools_;
  std::ostream& out_;
};

}  // namespace dream::workflows
