#pragma once

#include <atomic>

namespace dream::python_host {

/// `dream-agent-shared --python-host`: the process that hosts Python controllers for
/// PythonHostProcess, which started it with the link on descriptor 3, the
/// faulthandler pipe on 4 and the shared call cell on 5. Its own memq:// bus
/// holds the embedded Python host; the link relays the world's messages in and
/// its robots' messages out. It ends at the end of the link's stream (its
/// parent stops it), when the host ends, or when its parent kills it.
class PythonHostChild {
 public:
  /// The process's exit codes: the program's own list (dream::session's
  /// ExitCode), given by the program so this library stays below it. Only the
  /// parent reads them, and only 0 ("ended as asked") has a meaning to it.
  struct ExitCodes {
    int ok = 0;
    int usage = 2;
    int input_error = 1;
    int run_failed = 4;
  };

  /// Runs the process; `stop` is what the program's signal handlers set
  /// (Ctrl-C, SIGTERM), and it is set here too when the link to the parent
  /// breaks. Never returns: it ends with _exit, running no destructors.
  [[noreturn]] static void Run(std::atomic<bool>& stop, const ExitCodes& codes);
};

}  // namespace dream::python_host
