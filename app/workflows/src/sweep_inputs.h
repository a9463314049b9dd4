#pragma once

#include <string>
#include <vector>

#include "dream/workflows/sweep_folder.h"

namespace dream::workflows {

/// What a sweep was planned from, recorded as SHA-256 digests when it is
/// planned (inputs.sha256, in sha256sum's format: the base config by its
/// absolute path, then sweep.json and plan.tsv), so `dream sweep resume`
/// refuses to mix runs of different inputs into one table: an edited base
/// config, a sweep.json pointed at another experiment, an edited plan.
class SweepInputs {
 public:
  static constexpr const char* kFileName = "inputs.sha256";

  /// Records the digests of the base config at `config_path`, sweep.json and
  /// plan.tsv as they are now. @throws std::runtime_error when one cannot be read.
  static void Record(const SweepFolder& folder, const std::string& config_path);

  /// What changed since Record, for people: "the base config /x/y.yaml",
  /// "sweep.json", "plan.tsv"; empty when nothing did. `config_path`: the
  /// config sweep.json names now. `unchecked` gets what could not be checked
  /// (no record: a sweep planned by an older dream; the base config gone).
  static std::vector<std::string> Changed(const SweepFolder& folder, const std::string& config_path,
                                          std::string* unchecked);
};

}  // namespace dream::workflows
