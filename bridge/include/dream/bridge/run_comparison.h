#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dream/bridge/difference_stats.h"
#include "dream/world/violation_counts.h"

namespace dream::bridge {

/// One run's side of a comparison.
struct ComparedRun {
  std::string folder;
  /// What the run is, from its summary.json: "lab run (dream import)", "lab
  /// replay (dream lab-replay)", "simulation" or "simulation, world.realism
  /// on"; "run (no summary.json)" when it cannot tell.
  std::string what;
  int64_t steps = 0;                                                ///< last step with poses
  std::string end;                                                  ///< the final DREAM_STATUS detail
  world::ViolationCounts violations{};                              ///< from the final DREAM_STATUS
  std::string verdict;                                              ///< clean / warning / rejected
  double min_distance_m = std::numeric_limits<double>::infinity();  ///< closest two robot centres
  int64_t min_distance_step = -1;
  int min_distance_first = -1;
  int min_distance_second = -1;
  nlohmann::ordered_json metrics;  ///< the experiment's metrics, from the log
};

/// Errors of one robot, second run minus first, over the compared steps.
struct RobotTracking {
  int robot = 0;
  DifferenceStats position_m;   ///< distance between the robot's centres
  DifferenceStats heading_rad;  ///< heading difference, wrapped to [-pi, pi]
};

/// A simulated run against its lab run (or any two runs of one experiment).
struct RunComparison {
  ComparedRun first;           ///< usually the simulated run (the plan)
  ComparedRun second;          ///< usually the lab run; ComparedRun::what says what each is
  int64_t compared_steps = 0;  ///< steps 0..compared_steps are in both
  std::vector<RobotTracking> robots;
  DifferenceStats position_m;  ///< over every robot and compared step
  int max_robot = 0;           ///< the robot of position_m.max()

  /// A report for people: tracking per robot, closest approach, violations
  /// and the experiment's own metrics side by side.
  std::string Text() const;
  nlohmann::ordered_json Json() const;
};

/// Compares two run folders (each with run.lcmlog and config.yaml, as
/// written by dream run, dream import or dream lab-replay), step by step.
/// The experiment's metrics of both come from the first folder's config (a
/// Python controller's own ones too when `python_runtime_dir` is given).
/// @throws std::runtime_error naming the file when a folder is not a run, or
///         the runs have different robot counts.
RunComparison CompareRuns(const std::string& first_dir, const std::string& second_dir,
                          const std::string& python_runtime_dir = "");

/// CompareRuns, then writes out_dir/comparison.json and
/// out_dir/comparison.png (both atomically).
RunComparison CompareRunsAndWrite(const std::string& first_dir, const std::string& second_dir,
                                  const std::string& out_dir, const std::string& python_runtime_dir = "");

}  // namespace dream::bridge
