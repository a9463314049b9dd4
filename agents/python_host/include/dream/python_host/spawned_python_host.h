#pragma once

#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

namespace dream::python_host {

/// The process that hosts Python controllers (`dream-agent-shared --python-host`),
/// started in a process group of its own with the link to it (a socket), the
/// pipe its faulthandler writes tracebacks to, and the call cell the two share
/// (which call it is in, and since when) on its descriptors 3, 4 and 5.
/// PythonHostProcess owns what Start() returns: it closes the descriptors,
/// unmaps the cell and ends the group (KillAndReap).
struct SpawnedPythonHost {
  static constexpr size_t kCellBytes = 4096;

  pid_t pid = -1;
  int link_fd = -1;
  int trace_fd = -1;  // non-blocking
  std::atomic<int64_t>* cell = nullptr;

  /// @throws std::runtime_error naming the step that failed (socketpair,
  /// pipe, memfd, fork, exec of dream-agent-shared) and the OS error.
  static SpawnedPythonHost Start();
};

/// SIGKILL to the whole group of `pid` (whatever a controller forked
/// included), then `pid` itself is reaped; its wait status.
int KillAndReap(pid_t pid);

/// True when `pid` has ended (not reaped: its group stays killable); `how`,
/// if given, says how ("exit code N" or "killed by signal N (SIGX)").
bool HasEnded(pid_t pid, std::string* how = nullptr);

/// A wait status in words: "exit code N" or "killed by signal N (SIGX)".
std::string ExitTextOf(int status);

/// Appends what the faulthandler pipe `fd` holds now to `trace` (bounded).
void ReadTrace(int fd, std::string* trace);

/// Asks `pid`'s faulthandler for every thread's Python traceback (SIGUSR1)
/// and reads it from `trace_fd` into `trace` until it holds a whole frame of
/// `module_path`, or for at most `bound` (a dump without one).
void RequestTrace(pid_t pid, int trace_fd, const std::string& module_path, std::chrono::steady_clock::duration bound,
                  std::string* trace);

/// The innermost frame in `module_path` of a faulthandler dump ("  File
/// "/x/y.py", line 7 in update"), else in a file beside it (a helper it
/// imports); "" when neither is there.
std::string TracedLineOf(const std::string& trace, const std::string& module_path);

}  // namespace dream::python_host
