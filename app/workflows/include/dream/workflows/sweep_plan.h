#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "dream/config_overrides/sweep_parameter.h"

namespace dream::workflows {

/// Every run of a sweep: each combination of the --set values, for every
/// seed. Each run gets a folder-safe name (seed07_max_speed_mps-0.1) and its
/// own config, made from the base config's text.
class SweepPlan {
 public:
  struct Run {
    size_t index = 0;  ///< position in the plan, 0-based
    std::string name;  ///< folder name under <out>/runs/, unique in the plan
    uint64_t seed = 0;
    using Values = std::vector<std::pair<std::string, std::string>>;
    Values parameters;  ///< (key, value) in parameter_keys() order
    /// "seed 7" or "seed 7, max_speed_mps=0.1" for progress lines.
    std::string Label() const;
  };

  /// Every combination of the `parameters` (--set) with the `zipped` keys
  /// (--zip: varied together, the i-th values of each in one run), for every
  /// seed. @throws std::invalid_argument when a key is given twice, zipped
  /// keys differ in their number of values, there are no seeds, or there
  /// would be more than kMaxSweepRuns runs.
  SweepPlan(const std::vector<uint64_t>& seeds, const std::vector<config_overrides::SweepParameter>& parameters,
            const std::vector<config_overrides::SweepParameter>& zipped = {});

  /// A plan read back from a sweep folder (SweepFolder::ReadPlan): `runs`
  /// in index order, each with a value for every key. @throws
  /// std::invalid_argument when they are not.
  static SweepPlan FromRuns(std::vector<std::string> parameter_keys, std::vector<Run> runs);

  const std::vector<Run>& runs() const { return runs_; }
  /// The --set keys, then the --zip keys, in order (the table's parameter columns).
  const std::vector<std::string>& parameter_keys() const { return keys_; }

  /// The run's config: `base_text` parsed afresh (so lines in errors are the
  /// base file's), with `seed`, the run's parameters and `name` (the base
  /// config's name + "_" + run name) set. @throws std::invalid_argument for
  /// a key that cannot be set (see ApplyConfigOverride), or base text that is
  /// not a YAML mapping.
  static YAML::Node MakeRunConfig(const std::string& base_text, const std::string& source_name, const Run& run);
  /// The same from the base config parsed once (ParseBase), for the many runs
  /// of a sweep: a copy without the file's lines (YAML::Clone keeps none), so
  /// an error found in it is best reported from MakeRunConfig(base_text, ...).
  static YAML::Node MakeRunConfig(const YAML::Node& parsed_base, const std::string& source_name, const Run& run);
  /// `base_text` parsed. @throws std::invalid_argument naming the line, or
  /// when it is not a YAML mapping.
  static YAML::Node ParseBase(const std::string& base_text, const std::string& source_name);

 private:
  SweepPlan() = default;
  static void ApplyRun(YAML::Node& root, const std::string& source_name, const Run& run);
  void AddKey(const config_overrides::SweepParameter& parameter, const std::string& option);
  void AddRun(uint64_t seed, size_t seed_width, const Run::Values& values, std::set<std::string>* names);

  std::vector<Run> runs_;
  std::vector<std::string> keys_;
};

}  // namespace dream::workflows
