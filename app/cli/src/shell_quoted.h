#pragma once

#include <string>
#include <vector>

namespace dream::cli {

/// `text` quoted for a POSIX shell when it holds anything but safe characters
/// (URLs hold '&' and '?'), so a printed command can be pasted as is.
std::string ShellQuoted(const std::string& text);
/// The words of `argv`, each ShellQuoted, joined by spaces.
std::string ShellCommandLine(const std::vector<std::string>& argv);

}  // namespace dream::cli
