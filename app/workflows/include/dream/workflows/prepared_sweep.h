#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dream/run_config/run_config.h"
#include "dream/workflows/sweep_folder.h"
#include "dream/workflows/sweep_plan.h"
#include "dream/workflows/sweep_settings.h"

namespace dream::workflows {

/// A sweep checked before anything is written: the plan, and every run's
/// config generated from the base config and checked as `dream run` checks
/// it, so a bad value stops the sweep at once naming its run and line.
class PreparedSweep {
 public:
  /// `base`: the base config as `dream run` loads it (with --steps), already
  /// checked by the caller; `out_dir`: the sweep folder the run configs'
  /// comments name. @throws config::ConfigError or
  /// std::invalid_argument naming the option, run and key.
  PreparedSweep(const SweepSettings& settings, const run_config::RunConfig& base, const std::string& out_dir);

  const SweepPlan& plan() const { return plan_; }
  const std::string& base_name() const { return base_name_; }
  /// --seeds as given, or the base config's seed.
  const std::string& seeds_text() const { return seeds_text_; }
  size_t seed_count() const { return seed_count_; }
  /// The largest step limit of any run (for Slurm's default time limit).
  long long max_steps() const { return max_steps_; }

  /// Writes run `index`'s folder: its config.yaml (and the Python module it
  /// names, copied as `dream run` keeps it), its earlier outputs removed.
  void WriteRun(const SweepFolder& folder, size_t index) const;

 private:
  /// A python controller's module named by a relative path, as each run
  /// folder keeps a copy of it: its text, read when the sweep starts, so a
  /// run's config.yaml repeats the run even after the module is edited.
  struct ModuleCopy {
    std::string relative_path;  ///< as the config names it
    std::string text;
  };

  /// What every run's config is made from, and what the runs share.
  struct RunConfigMaker;
  void PrepareRun(RunConfigMaker& maker, const SweepPlan::Run& run);

  SweepPlan plan_;
  std::string base_name_;
  std::string seeds_text_;
  size_t seed_count_ = 0;
  long long max_steps_ = 0;
  std::vector<std::string> config_texts_;
  /// Per run (null: none to copy); runs naming the same file share one copy.
  std::vector<std::shared_ptr<const ModuleCopy>> modules_;
};

}  // namespace dream::workflows
