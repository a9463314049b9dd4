#pragma once

#include <string>
#include <vector>

namespace dream::config_overrides {

/// One `--set KEY=V1,V2,...` of a sweep: a dotted path into the run config
/// (controller.max_speed_mps, controller.sensors.0.noise_std) and the values
/// it takes, each a YAML value ("0.1", "thesis", "[0.5, 0]").
struct SweepParameter {
  std::string key;
  std::vector<std::string> values;

  /// Parses "KEY=V1,V2,...". Values split at commas outside brackets, braces
  /// and quotes, so "initial_poses.0=[0,0,0],[0.5,0,0]" gives two lists.
  /// @throws std::invalid_argument naming the option and the bad part.
  static SweepParameter Parse(const std::string& text);

  /// The syntax Parse shares with `dream run --set KEY=VALUE`, without the
  /// sweep's own rules (seed and name are allowed). `expected` completes
  /// "expected ..." when there is no '='.
  static SweepParameter ParseAssignment(const std::string& text, const std::string& expected);

  /// The last part of the key that tells runs apart: "max_speed_mps", or
  /// "sensors.0.noise_std" -> "noise_std", "initial_poses.3" -> "initial_poses.3".
  std::string ShortName() const;
};

}  // namespace dream::config_overrides
