#pragma once

#include <string>
#include <vector>

namespace dream::workflows {

/// `text` quoted for a POSIX shell when it holds anything but safe characters
/// (URLs hold '&' and '?'), so a printed command can be pasted as is and a
/// written script (a sweep's run.sh, its Slurm jobs) reads every word back.
std::string ShellQuoted(const std::string& text);
/// The words of `argv`, each ShellQuoted, joined by spaces.
std::string ShellCommandLine(const std::vector<std::string>& argv);

}  // namespace dream::workflows
