#pragma once

#include <string>
#include <vector>

namespace dream::cli {

/// LCM's own windows that `dream spy` and `dream replay` open (lcm-spy, the
/// log player): Java programs started from lcm.jar, with what both commands
/// need to check, print and run them.

/// `path` when it exists; else throws naming `what`, the path and `hint` (the
/// package to install).
std::string RequireToolFile(const std::string& path, const char* what, const char* hint);
/// Debian's lcm.jar (liblcm-java), which holds both tools.
std::string RequireLcmJar();
/// lcm-spy's classpath: lcm.jar, jchart2d.jar and the dream types jar
/// ($DREAM_TYPES_JAR, else the build tree's or the installed one), each
/// checked, so a missing one is named before any window starts.
std::string SpyClasspath();

/// `--print`: each non-empty command on a line of its own, quoted for a shell.
void PrintToolCommands(const std::vector<std::vector<std::string>>& commands);

/// Starts each non-empty command in order, `pause_s` seconds apart (so a
/// window can subscribe before a player starts), and waits until command
/// `wait_for` exits; Ctrl-C or SIGTERM is passed on to every one (and starts
/// no further one). Exit: kExitOk when it exited 0, kExitInterrupted when the
/// user stopped it, else kExitRunFailed.
int RunToolsUntilClosed(const std::vector<std::vector<std::string>>& commands, size_t wait_for, unsigned pause_s);

}  // namespace dream::cli
