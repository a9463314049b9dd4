#pragma once

#include <string>

namespace dream::cli {

/// LCM's Java windows (lcm-spy, the log player) need a display. Without one
/// the JVM prints a HeadlessException and, its LCM threads still running,
/// never exits: refuse before starting it.
/// @throws std::runtime_error saying which window, why, and what to do instead
/// (`instead`, e.g. "dream replay RUN --print prints the command").
void RequireWindowDisplay(const std::string& window, const std::string& instead);

}  // namespace dream::cli
