#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace dream::cli {

/// Child processes started by one `dream` command (launch, spy). Children
/// get SIGTERM when the group is destroyed, so none outlives its parent.
class ProcessGroup {
 public:
  ProcessGroup() = default;
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  /// Starts `argv[0]` (searched on PATH) with `argv`. @throws std::runtime_error.
  pid_t Start(const std::vector<std::string>& argv);
  /// The same, with stdout and stderr written to `output_path` (created or
  /// truncated) and stdin from /dev/null (dream sweep's children).
  pid_t Start(const std::vector<std::string>& argv, const std::string& output_path);
  /// Waits for `pid`; returns its exit code (128 + signal when killed).
  int Wait(pid_t pid);
  /// Waits for `pid` up to `timeout_s`; returns its exit code or -1 on timeout.
  int WaitFor(pid_t pid, double timeout_s);
  /// Its exit code if `pid` has ended, else -1 at once.
  int TryWait(pid_t pid);
  /// Sends `signal` to every child still running.
  void SignalAll(int signal);

 private:
  std::vector<pid_t> running_;
};

/// The path of the running executable (/proc/self/exe).
std::string SelfExecutable();

}  // namespace dream::cli
