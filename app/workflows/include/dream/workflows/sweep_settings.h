#pragma once

#include <string>
#include <vector>

namespace dream::workflows {

/// What `dream sweep CONFIG ...` was asked to do (docs/sweeps.md).
struct SweepSettings {
  /// Where the runs run: this machine's cores, a Slurm job array, or
  /// nowhere (the plan and one shell command per run, for other schedulers).
  enum class Engine { kLocal, kSlurm, kPlan };

  std::string config_path;
  std::string seeds;              ///< "1-20", "7", "1,4,9-12"; empty: the config's seed
  std::vector<std::string> sets;  ///< "KEY=V1,V2,..." each: every combination runs
  std::vector<std::string> zips;  ///< "KEY=V1,V2,..." each: varied together, the i-th values in one run
  int jobs = 0;                   ///< runs at once; 0: local one per core, Slurm no limit
  long long steps = 0;            ///< 0: the config's step limit
  std::string out_dir;            ///< empty: sweeps/<name> (or _2, ... when that holds a sweep)
  double run_timeout_s = 1800.0;  ///< local: a run still going after this is stopped and counts as failed
  Engine engine = Engine::kLocal;
  std::vector<std::string> slurm_options;  ///< passed on to sbatch as they are
  /// The Python runtime (DataFiles::PythonRuntimeDir()): a sweep of a
  /// Robotarium script (config_path a .py file) names its rps_dream there.
  std::string python_runtime_dir;

  /// The text of the base config: the file's, or for a script the config
  /// ScriptRunWorkflow::BaseConfigText makes of it. @throws config::ConfigError.
  std::string BaseConfigText() const;

  /// "local", "slurm", "plan" -> Engine. @throws std::invalid_argument naming the choices.
  static Engine ParseEngine(const std::string& name);
  static std::string EngineName(Engine engine);
};

}  // namespace dream::workflows
