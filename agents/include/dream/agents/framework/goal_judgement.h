#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace dream::agents {

/// Whether a run met its experiment's own goal: the kind's success rule
/// (ExperimentMetrics::JudgeGoal) applied to its figures. summary.json keeps
/// it under metrics.goal; sweeps, the verdict and export read it there, so no
/// code outside a kind's own files knows the kind's rule.
struct GoalJudgement {
  bool met = false;
  int64_t completion_step = -1;  ///< the step the goal was reached, -1: never
  std::string detail;            ///< short, for tables: "3 of 3 formations", "not settled"

  /// "0.0123 m": lengths in details.
  static std::string Metres(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g m", value);
    return text;
  }

  /// `value` as Metres does, with more digits when three would print it as
  /// `reference` (a tolerance it missed by 0.0000082 m must not read
  /// "0.02 m" against 0.02 m): "0.02001 m".
  static std::string MetresApart(double value, double reference) {
    char text[32];
    char other[32];
    for (int digits = 3; digits <= 17; ++digits) {
      std::snprintf(text, sizeof(text), "%.*g m", digits, value);
      std::snprintf(other, sizeof(other), "%.*g m", digits, reference);
      if (value == reference || std::string(text) != other) break;
    }
    return text;
  }
};

}  // namespace dream::agents
