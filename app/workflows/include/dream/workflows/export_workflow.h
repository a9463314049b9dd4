#pragma once

#include <atomic>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

#include "dream/bridge/export_options.h"
#include "dream/bridge/submission_exporter.h"

namespace dream::workflows {

/// `dream export RUN`: a recorded run becomes a Robotarium submission
/// (bridge::ExportSubmission) in its own folder, exports/<name> unless told
/// otherwise, and what to upload is printed. A run the lab would refuse is a
/// result, not an error: nothing is written and the refusal says why.
class ExportWorkflow {
 public:
  struct Options {
    std::string run_dir;      ///< a folder dream run wrote
    std::string out_dir;      ///< empty: exports/<the config's name> (made with its parent)
    std::string config_path;  ///< empty: <run_dir>/config.yaml
    bridge::ExportOptions exporter;
  };

  struct Result {
    bool refused = false;
    std::string refusal;            ///< why the lab would refuse the run (ExportRefused::what)
    bridge::ExportSummary summary;  ///< what was written, when not refused
  };

  /// What `dream export` is asked, as typed: a recorded run exported, or
  /// (`calibration`) the calibration drive run on `robots` robots, then exported.
  struct Asked {
    std::string run_dir;       ///< a folder written by dream run (calibration: the run folder to write)
    std::string out_dir;       ///< empty: exports/<name>
    std::string config_path;   ///< empty: <run_dir>/config.yaml
    std::string strategy;      ///< empty: track (calibration: replay)
    bool calibration = false;  ///< run the calibration drive on `robots` robots, then export it
    int robots = 0;            ///< with calibration only; 0: not given
    bool barriers = false;
    int settle_steps = 240;
    bool force = false;                       ///< export although robots were lost
    std::string python_runtime_dir;           ///< DREAM's Python package (a Python controller's export)
    const std::atomic<bool>* stop = nullptr;  ///< ends the calibration drive early (Ctrl-C)
  };

  explicit ExportWorkflow(std::ostream& out = std::cout) : out_(out) {}

  /// The names `Asked::strategy` takes (bridge::StrategyNames).
  static std::vector<std::string> StrategyNames();

  /// Refuses what does not go together (std::runtime_error naming the
  /// options), then exports, or runs the calibration export
  /// (CalibrationExportWorkflow). Returns the exit code (session::ExitCode);
  /// an export the lab would refuse is kExitRejected with `*refusal` saying
  /// why and nothing written.
  int ExportAsAsked(const Asked& asked, std::string* refusal) const;

  /// @throws std::runtime_error (or config::ConfigError) naming the file for
  ///         input that cannot be read.
  Result Export(const Options& options) const;

  /// Where the export goes: `options.out_dir`, else exports/<name> of the
  /// run's config.
  static std::string OutDir(const Options& options);

 private:
  std::ostream& out_;
};

}  // namespace dream::workflows
