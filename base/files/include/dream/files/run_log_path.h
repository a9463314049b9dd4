#pragma once

#include <string>

namespace dream::files {

/// The log a command reads when given a run: `run_or_log` itself when it is a
/// file, else its run.lcmlog (a run folder written by dream run).
/// @throws std::runtime_error naming the path when neither is there.
std::string RunLogPath(const std::string& run_or_log);

}  // namespace dream::files
