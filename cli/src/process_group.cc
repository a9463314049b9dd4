#include "process_group.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace dream::cli {

ProcessGroup::~ProcessGroup() {
  SignalAll(SIGTERM);
  for (pid_t pid : std::vector<pid_t>(running_)) {
    if (WaitFor(pid, 5.0) < 0) {
      ::kill(pid, SIGKILL);
      Wait(pid);
    }
  }
}

pid_t ProcessGroup::Start(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int error = ::posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ);
  if (error != 0) {
    throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(error));
  }
  running_.push_back(pid);
  return pid;
}

int ProcessGroup::Wait(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  running_.erase(std::remove(running_.begin(), running_.end(), pid), running_.end());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int ProcessGroup::WaitFor(pid_t pid, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) {
      running_.erase(std::remove(running_.begin(), running_.end(), pid), running_.end());
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

void ProcessGroup::SignalAll(int signal) {
  for (pid_t pid : running_) ::kill(pid, signal);
}

std::string SelfExecutable() {
  char path[4096];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (n <= 0) throw std::runtime_error("cannot find the dream executable (/proc/self/exe)");
  path[n] = '\0';
  return path;
}

}  // namespace dream::cli
