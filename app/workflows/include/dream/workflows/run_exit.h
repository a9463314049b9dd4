#pragma once

#include <optional>
#include <string>

namespace dream::workflows {

/// How one run's `dream run` process ended, as the sweep folder keeps it in
/// runs/<run>/exit.txt, written last (atomically) by whoever waited for the
/// process: the local engine, or run.sh on a cluster node. A run folder
/// without it holds no finished run (a task killed half way, or never
/// started), so a run is counted only once this record exists.
///
/// The file: "EXIT_CODE WALL_TIME_S TIMED_OUT(0|1)\n", then optionally one
/// line saying why the process could not start.
struct RunExit {
  static constexpr const char* kFileName = "exit.txt";
  /// Larger files are not a record of ours.
  static constexpr size_t kMaxBytes = 4096;

  int exit_code = -1;        ///< of dream run; 128 + signal when killed; -1 when it could not start
  double wall_time_s = 0.0;  ///< start of the process to its exit
  bool timed_out = false;    ///< stopped at the sweep's --timeout
  std::string problem;       ///< why it could not start (exit_code -1), else empty

  std::string Text() const;
  /// Parses a record; nullopt when `text` is not one (damaged or foreign).
  static std::optional<RunExit> Parse(const std::string& text);
};

}  // namespace dream::workflows
