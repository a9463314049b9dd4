#pragma once

#include <atomic>
#include <iostream>
#include <optional>
#include <ostream>
#include <string>

#include "dream/bridge/export_options.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/session/exit_code.h"

namespace dream::workflows {

/// `dream export --calibration --robots N` (docs/calibration.md): the
/// calibration drive's config for N robots, run as dream run runs a config
/// (the ideal world, every agent in this process:
/// session::RunSession::RunWithAgents), then exported open loop (strategy
/// replay: the program's commands, which calibrate fits the lab's response
/// to). A run that is not clean is not exported.
class CalibrationExportWorkflow {
 public:
  struct Options {
    int robots = 0;                        ///< CalibrationConfig::kMinRobots to kMaxRobots
    std::string out_dir;                   ///< the export; empty: exports/calibration_<N>
    std::string run_dir;                   ///< the simulated run; empty: runs/calibration_<N> (or _2, ...)
    bridge::ExportOptions export_options;  ///< strategy and calibration are set here
    /// Ends the run early when set (Ctrl-C); none: it ends by itself.
    const std::atomic<bool>* stop = nullptr;
  };

  struct Result {
    session::ExitCode exit_code = session::kExitOk;
    std::string run_dir;                            ///< where the run was written
    std::optional<bridge::ExportSummary> exported;  ///< none: nothing was exported
  };

  /// `out` takes the export's instructions, `err` why nothing was exported.
  explicit CalibrationExportWorkflow(std::ostream& out = std::cout, std::ostream& err = std::cerr)
      : out_(&out), err_(&err) {}

  /// @throws std::runtime_error naming the option (--robots, --out, the run
  ///         folder) before anything runs: robots out of range, a folder
  ///         holding a run, one folder for both.
  Result Export(const Options& options) const;

 private:
  std::ostream* out_;
  std::ostream* err_;
};

}  // namespace dream::workflows
