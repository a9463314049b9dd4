#include "dream/python_host/spawned_python_host.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <regex>
#include <stdexcept>

#include "dream/process/data_files.h"

namespace dream::python_host {
namespace {

using Clock = std::chrono::steady_clock;

// Where the process finds what its parent gives it (python_host_child.cc).
constexpr int kChildLinkFd = 3;
constexpr int kChildTraceFd = 4;
constexpr int kChildCellFd = 5;
constexpr size_t kMaxTraceBytes = 1 << 16;

[[noreturn]] void ThrowErrno(const std::string& what) {
  throw std::runtime_error("cannot start the process for the Python controllers: " + what + ": " +
                           std::strerror(errno));
}

}  // namespace

// dream-agent-shared --python-host in its own process group, with the link,
// the faulthandler pipe and the shared call cell on descriptors 3, 4 and 5.
// The shared build: the embedded module it loads links the shared dream
// libraries, which dream-agent holds a copy of.
SpawnedPythonHost SpawnedPythonHost::Start() {
  const std::string binary = process::DataFiles::SharedAgentBinary();
  const std::string option = "--python-host";
  char* argv[] = {const_cast<char*>(binary.c_str()), const_cast<char*>(option.c_str()), nullptr};
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) ThrowErrno("socketpair");
  int trace[2];
  if (::pipe2(trace, O_CLOEXEC) != 0) ThrowErrno("pipe");
  const int cell_fd = ::memfd_create("dream-python-call-cell", MFD_CLOEXEC);
  if (cell_fd < 0 || ::ftruncate(cell_fd, SpawnedPythonHost::kCellBytes) != 0) ThrowErrno("memfd");
  void* cell = ::mmap(nullptr, SpawnedPythonHost::kCellBytes, PROT_READ | PROT_WRITE, MAP_SHARED, cell_fd, 0);
  if (cell == MAP_FAILED) ThrowErrno("mmap");
  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) ThrowErrno("pipe");
  // Its stdin: not the terminal, which a process outside the foreground
  // group may not read (SIGTTIN would stop it).
  const int null_fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (null_fd < 0) ThrowErrno("/dev/null");
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) ThrowErrno("fork");
  if (pid == 0) {
    // Only async-signal-safe calls until exec. Its own group: the terminal's
    // Ctrl-C is the parent's to handle, and the group is what the parent kills.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int link = ::fcntl(sockets[1], F_DUPFD_CLOEXEC, 10);
    const int trace_out = ::fcntl(trace[1], F_DUPFD_CLOEXEC, 10);
    const int cell_in = ::fcntl(cell_fd, F_DUPFD_CLOEXEC, 10);
    int error = 0;
    if (link < 0 || trace_out < 0 || cell_in < 0 || ::dup2(null_fd, STDIN_FILENO) < 0 ||
        ::dup2(link, kChildLinkFd) < 0 || ::dup2(trace_out, kChildTraceFd) < 0 || ::dup2(cell_in, kChildCellFd) < 0) {
      error = errno;
    } else {
      ::execv(binary.c_str(), argv);
      error = errno;
    }
    const ssize_t written = ::write(report[1], &error, sizeof error);
    (void)written;
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // as the child does: whichever runs first
  ::close(sockets[1]);
  ::close(trace[1]);
  ::close(cell_fd);
  ::close(null_fd);
  ::close(report[1]);
  int error = 0;
  ssize_t got = 0;
  while ((got = ::read(report[0], &error, sizeof error)) < 0 && errno == EINTR) {
  }
  ::close(report[0]);
  if (got > 0) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    ::close(sockets[0]);
    ::close(trace[0]);
    ::munmap(cell, SpawnedPythonHost::kCellBytes);
    errno = error;
    ThrowErrno(binary);
  }
  ::fcntl(trace[0], F_SETFL, O_NONBLOCK);
  return {pid, sockets[0], trace[0], static_cast<std::atomic<int64_t>*>(cell)};
}

// Reads what the faulthandler pipe holds now (bounded).
void ReadTrace(int fd, std::string* trace) {
  char chunk[4096];
  ssize_t n = 0;
  while ((n = ::read(fd, chunk, sizeof chunk)) > 0) {
    if (trace->size() < kMaxTraceBytes) trace->append(chunk, std::min<size_t>(n, kMaxTraceBytes - trace->size()));
  }
}

// The innermost frame in `module_path` of a faulthandler dump ("  File
// "/x/y.py", line 7 in update"), else in a file beside it (a helper it
// imports); "" when neither is there (the dump holds the innermost 100
// frames only, e.g. all inside the standard library).
std::string TracedLineOf(const std::string& trace, const std::string& module_path) {
  static const std::regex kFrame(R"re(File "([^"\n]*)", line (\d+) in (\S+))re");
  const std::string folder = module_path.substr(0, module_path.rfind('/') + 1);
  std::string beside;
  for (auto it = std::sregex_iterator(trace.begin(), trace.end(), kFrame); it != std::sregex_iterator(); ++it) {
    const std::string file = (*it)[1].str();
    const std::string where = file + ":" + (*it)[2].str() + ": in " + (*it)[3].str();
    if (!module_path.empty() && file == module_path) return where;
    if (beside.empty() && !folder.empty() && file.rfind(folder, 0) == 0) beside = where;
  }
  return beside;
}

std::string ExitTextOf(int status) {
  if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    return "killed by signal " + std::to_string(signal) + (name != nullptr ? std::string(" (SIG") + name + ")" : "");
  }
  return "status " + std::to_string(status);
}

// SIGKILL to the whole group (whatever a controller forked included), then
// the process itself is reaped; its status.
int KillAndReap(pid_t pid) {
  ::kill(-pid, SIGKILL);
  ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

// True when `pid` has ended (not reaped: its group stays killable); `how`,
// if given, says how ("exit code N" or "killed by signal N (SIGX)").
bool HasEnded(pid_t pid, std::string* how) {
  siginfo_t info{};
  if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0 || info.si_pid != pid) {
    return false;
  }
  if (how != nullptr) {
    *how = ExitTextOf(info.si_code == CLD_EXITED ? W_EXITCODE(info.si_status, 0) : info.si_status);
  }
  return true;
}

// SIGUSR1 makes faulthandler write every thread's Python traceback. It is
// read until it holds a whole frame of the module (the line a fault names),
// not for a quiet moment: a starved child writes late, not less.
void RequestTrace(pid_t pid, int trace_fd, const std::string& module_path, Clock::duration bound, std::string* trace) {
  const size_t before = trace->size();
  const std::string frame = "File \"" + module_path + "\", line ";
  const auto has_module_frame = [&] {
    const size_t at = module_path.empty() ? std::string::npos : trace->find(frame, before);
    return at != std::string::npos && trace->find('\n', at) != std::string::npos;
  };
  ::kill(pid, SIGUSR1);
  const auto until = Clock::now() + bound;
  while (!has_module_frame()) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - Clock::now()).count();
    if (left <= 0) break;
    pollfd fd{trace_fd, POLLIN, 0};
    const int ready = ::poll(&fd, 1, static_cast<int>(std::min<int64_t>(left, 100)));
    if (ready > 0 && (fd.revents & POLLIN) != 0) {
      ReadTrace(trace_fd, trace);
    } else if (ready > 0) {
      break;  // the pipe's writer is gone
    }
  }
}

}  // namespace dream::python_host
