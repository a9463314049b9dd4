#include "dream/process/process_group.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace dream::process {

ProcessGroup::~ProcessGroup() {
  SignalAll(SIGTERM);
  for (pid_t pid : std::vector<pid_t>(running_)) {
    if (WaitFor(pid, 5.0) < 0) {
      ::kill(pid, SIGKILL);
      Wait(pid);
    }
  }
}

namespace {

// In the child, before exec (async-signal-safe calls only): stdin from
// /dev/null, stdout and stderr to `output_path`. O_NOFOLLOW: a link planted
// at the output's name is not written through; O_NONBLOCK and the check: a
// FIFO there is refused, not waited on. 0, or the errno to report.
int RedirectToFile(const std::string& output_path) {
  const int in = ::open("/dev/null", O_RDONLY);
  const int out = ::open(output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK, 0644);
  struct stat status {};
  if (out >= 0 && (::fstat(out, &status) != 0 || !S_ISREG(status.st_mode))) return EINVAL;
  if (in < 0 || out < 0 || ::fcntl(out, F_SETFL, 0) != 0 || ::dup2(in, STDIN_FILENO) < 0 ||
      ::dup2(out, STDOUT_FILENO) < 0 || ::dup2(out, STDERR_FILENO) < 0) {
    return errno;
  }
  return 0;
}

}  // namespace

pid_t ProcessGroup::Start(const std::vector<std::string>& argv) { return Start(argv, std::string(), {}, -1); }

pid_t ProcessGroup::Start(const std::vector<std::string>& argv, const std::string& output_path) {
  return Start(argv, output_path, {}, -1);
}

pid_t ProcessGroup::Start(const std::vector<std::string>& argv, const std::string& output_path,
                          const std::vector<std::string>& extra_env, int inherited_fd) {
  return Start(argv, output_path, extra_env, inherited_fd >= 0 ? std::vector<int>{inherited_fd} : std::vector<int>{});
}

pid_t ProcessGroup::Start(const std::vector<std::string>& argv, const std::string& output_path,
                          const std::vector<std::string>& extra_env, const std::vector<int>& inherited_fds) {
  if (argv.empty()) throw std::invalid_argument("ProcessGroup::Start: no program");
  // Everything the child needs is made before fork(): after it, the child
  // calls only async-signal-safe functions.
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> environment;
  for (char** variable = environ; *variable != nullptr; ++variable) environment.emplace_back(*variable);
  environment.insert(environment.end(), extra_env.begin(), extra_env.end());
  std::vector<char*> envp;
  for (std::string& variable : environment) envp.push_back(variable.data());
  envp.push_back(nullptr);
  // Search PATH as posix_spawnp would, here rather than in the child.
  std::string program = argv[0];
  if (program.find('/') == std::string::npos) {
    const char* path = std::getenv("PATH");
    std::string dirs = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
    for (size_t start = 0; start <= dirs.size();) {
      const size_t end = std::min(dirs.find(':', start), dirs.size());
      const std::string candidate = (end > start ? dirs.substr(start, end - start) : ".") + "/" + argv[0];
      if (::access(candidate.c_str(), X_OK) == 0) {
        program = candidate;
        break;
      }
      start = end + 1;
    }
  }
  // The child reports a failed exec through this pipe; a successful exec closes it.
  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(errno) +
                             (errno == EMFILE ? " (raise the limit with ulimit -n)" : ""));
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(report[0]);
    ::close(report[1]);
    throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(error));
  }
  if (pid == 0) {
    // Dies with the parent; if the parent died before prctl, it is already gone.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(127);
    int error = output_path.empty() ? 0 : RedirectToFile(output_path);
    for (const int fd : inherited_fds) {
      if (error == 0 && ::fcntl(fd, F_SETFD, 0) != 0) error = errno;
    }
    if (error == 0) {
      ::execve(program.c_str(), args.data(), envp.data());
      error = errno;
    }
    const ssize_t written = ::write(report[1], &error, sizeof(error));
    (void)written;
    ::_exit(127);
  }
  ::close(report[1]);
  int error = 0;
  ssize_t got = 0;
  while ((got = ::read(report[0], &error, sizeof(error))) < 0 && errno == EINTR) {
  }
  ::close(report[0]);
  if (got > 0) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(error));
  }
  running_.push_back(pid);
  return pid;
}

int ProcessGroup::Reaped(pid_t pid, int status) {
  running_.erase(std::remove(running_.begin(), running_.end(), pid), running_.end());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int ProcessGroup::Wait(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return Reaped(pid, status);
}

int ProcessGroup::WaitFor(pid_t pid, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    const int code = TryWait(pid);
    if (code >= 0) return code;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

int ProcessGroup::TryWait(pid_t pid) {
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(pid, &status, WNOHANG)) < 0 && errno == EINTR) {
  }
  if (done != pid) return -1;
  return Reaped(pid, status);
}

int ProcessGroup::WaitPassingOnStop(pid_t pid, const std::atomic<bool>& stop, int stop_signal) {
  int code = -1;
  while ((code = WaitFor(pid, 0.1)) < 0) {
    if (stop.load()) SignalAll(stop_signal);
  }
  return code;
}

void ProcessGroup::SignalAll(int signal) {
  for (pid_t pid : running_) ::kill(pid, signal);
}

void ProcessGroup::RequireDescriptors(int needed) {
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) return;  // nothing to check against
  const auto wanted = static_cast<rlim_t>(needed);
  if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= wanted) return;
  if (limit.rlim_max == RLIM_INFINITY || limit.rlim_max >= wanted) {
    limit.rlim_cur = wanted;
    if (::setrlimit(RLIMIT_NOFILE, &limit) == 0) return;
  }
  throw std::runtime_error("too few file descriptors: limit " + std::to_string(limit.rlim_cur) + ", need about " +
                           std::to_string(needed) + " per process; raise with ulimit -n " + std::to_string(needed));
}

std::string SelfExecutable() {
  char path[4096];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (n <= 0) throw std::runtime_error("cannot find the dream executable (/proc/self/exe)");
  path[n] = '\0';
  return path;
}

}  // namespace dream::process
