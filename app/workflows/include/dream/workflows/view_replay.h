#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "dream/run_verdict_t.hpp"
#include "dream/view/view_setup.h"

namespace dream::workflows {

/// A finished run as dream view replays it: the page's setup (the config's
/// goals, sensors and radio; summary.json's judgement and metrics) and
/// /run.json. What `dream view RUN` serves and what `dream run --view`
/// turns into at the run's end, built once here so both show the same.
struct ViewReplay {
  view::ViewSetup setup;
  std::string run_json;    ///< RunReplayJson
  size_t steps = 0;        ///< steps with poses in the log
  int64_t first_step = 0;  ///< the log's first and last step with poses
  int64_t last_step = 0;

  /// `run`: a run folder or an .lcmlog; `config_path`: the run's config, or
  /// "" for config.yaml beside the log (a warning when that one cannot be
  /// used); `python_runtime_dir`: a Python controller's goal points when
  /// summary.json has none (ViewSetupOfConfig).
  /// @throws std::runtime_error naming the file when the log has no poses or
  ///         a given config cannot be read or is another run's.
  static ViewReplay OfRun(const std::string& run, const std::string& config_path,
                          const std::string& python_runtime_dir);

  /// The run's judgement from summary.json beside its log: what the page shows
  /// as the verdict at the run's end (none without a readable summary; a
  /// summary that cannot be read is only logged).
  static std::optional<view::ViewSetup::Judged> JudgedOfRun(const std::string& log_path);

  /// The run's judgement from the DREAM_VERDICT its log ends with: for a log
  /// replayed without its summary.json (none for a verdict none of the four).
  static std::optional<view::ViewSetup::Judged> JudgedOfVerdict(const run_verdict_t& verdict);
};

}  // namespace dream::workflows
