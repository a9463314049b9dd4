#pragma once

#include <iostream>
#include <ostream>
#include <string>

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

  explicit ExportWorkflow(std::ostream& out = std::cout) : out_(out) {}

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
