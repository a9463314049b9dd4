#pragma once

#include <sys/types.h>

#include <atomic>
#include <string>
#include <vector>

namespace dream::process {

/// Child processes started by one `dream` command (launch, sweep, spy).
/// None outlives its parent: each gets SIGTERM when the group is destroyed,
/// and the kernel sends it SIGTERM when the parent dies any other way
/// (PR_SET_PDEATHSIG, even after SIGKILL).
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
  /// The same, with `extra_env` ("NAME=value") added to the environment and
  /// the descriptor `inherited_fd` (if >= 0) left open in the child.
  pid_t Start(const std::vector<std::string>& argv, const std::string& output_path,
              const std::vector<std::string>& extra_env, int inherited_fd);
  /// The same with several descriptors left open in the child.
  pid_t Start(const std::vector<std::string>& argv, const std::string& output_path,
              const std::vector<std::string>& extra_env, const std::vector<int>& inherited_fds);
  /// Waits for `pid`; returns its exit code (128 + signal when killed).
  int Wait(pid_t pid);
  /// Waits for `pid` up to `timeout_s`; returns its exit code or -1 on timeout.
  int WaitFor(pid_t pid, double timeout_s);
  /// Its exit code if `pid` has ended, else -1 at once.
  int TryWait(pid_t pid);
  /// Waits for `pid`; once `stop` is set (Ctrl-C), sends `stop_signal` to
  /// every child still running, again every 0.1 s until `pid` ends, so that
  /// the children end with this command. Returns `pid`'s exit code.
  int WaitPassingOnStop(pid_t pid, const std::atomic<bool>& stop, int stop_signal);
  /// Sends `signal` to every child still running.
  void SignalAll(int signal);

  /// Checks, before any child starts, that each process (this one and its
  /// children, which inherit the limit) may open about `needed` descriptors:
  /// raises the soft limit up to the hard one if that is enough, else throws
  /// "too few file descriptors: limit N, need about M; raise with ulimit -n".
  /// (Without it, LCM failed to open its sockets in every child and the run
  /// stalled until the agents timed out.)
  static void RequireDescriptors(int needed);

 private:
  /// Forgets the ended `pid`; returns its exit code from waitpid's `status`.
  int Reaped(pid_t pid, int status);

  std::vector<pid_t> running_;
};

/// The path of the running executable (/proc/self/exe).
std::string SelfExecutable();

}  // namespace dream::process
