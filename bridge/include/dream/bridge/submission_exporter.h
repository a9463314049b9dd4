#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "dream/bridge/export_options.h"
#include "dream/bridge/pre_validation.h"

namespace dream::bridge {

/// The lab would refuse the run; problems() says why, per rule, robot and step.
/// what() starts with the run's log file, whose steps the problems count
/// (a damaged log reads as a refused run: it must say which file).
class ExportRefused : public std::runtime_error {
 public:
  ExportRefused(const std::string& log_file, std::vector<ExportProblem> problems);
  const std::vector<ExportProblem>& problems() const { return problems_; }

 private:
  std::vector<ExportProblem> problems_;
};

/// What an export wrote.
struct ExportSummary {
  std::string out_dir;
  std::string upload_dir;            ///< out_dir/upload: exactly the files to upload
  std::vector<std::string> uploads;  ///< their names; the first is the main script
  int num_robots = 0;
  int64_t steps = 0;
  int64_t max_iterations = 0;         ///< steps + settle steps
  double estimated_duration_s = 0.0;  ///< max_iterations x time step
  std::vector<std::string> warnings;  ///< StartUpWarnings: risks, not refusals
  std::string instructions;           ///< the text of UPLOAD.txt
};

/// Turns a recorded run (a folder written by `dream run`: run.lcmlog and
/// config.yaml) into a Robotarium submission in `out_dir`:
///   upload/dream_main.py      the main script (a fixed template, no data)
///   upload/dream_*.npy        its data: parameters, start poses, the
///                             recorded poses and velocities of every step
///                             (track, replay), or (controller) the
///                             controller spec and the obstacles per step
///   upload/dream*.py, <m>.py  (controller) the flat Python runtime and the
///                             run's controller module
///   UPLOAD.txt                what to upload, which file is main, the robot
///                             count and duration to declare
///   export.json, config.yaml  for dream import / compare (not uploaded)
/// Every file is written atomically, only after the run passed PreValidate
/// (and, for the controller strategy, when its controller is of kind python).
/// @param config_path the run's config; empty: run_dir/config.yaml.
/// @throws ExportRefused when the lab would refuse the run; std::runtime_error
///         (or config::ConfigError) naming the file for unreadable input.
ExportSummary ExportSubmission(const std::string& run_dir, const std::string& out_dir, const ExportOptions& options,
                               const std::string& config_path = "");

/// The submission script: bridge/python/dream_main.py, built into the binary.
const std::string& SubmissionScriptTemplate();

}  // namespace dream::bridge
