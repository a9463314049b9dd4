#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dream::agents {

/// An experiment's own outcome figures, for the run summary: named numbers
/// and named series of (step, value). Units go in the names (min_distance_m).
struct MetricsReport {
  std::map<std::string, double> values;
  std::map<std::string, std::vector<std::pair<int64_t, double>>> series;
  std::map<std::string, std::vector<int64_t>> steps;  ///< named lists of steps (events)
  /// A line a figure is judged against (the goal's tolerance, the collision
  /// distance), drawn on its plot over time (dream view); not in summary.json.
  struct Threshold {
    double value = 0.0;
    std::string label;  ///< what the line is: "goal: within 0.05 m"
  };
  std::map<std::string, Threshold> thresholds;  ///< by the name of the figure or series it applies to

  /// The value named `name`, or `fallback` when there is none.
  double Value(const std::string& name, double fallback = -1.0) const {
    const auto it = values.find(name);
    return it == values.end() ? fallback : it->second;
  }
};

}  // namespace dream::agents
