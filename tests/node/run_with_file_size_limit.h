#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <map>
#include <sstream>
#include <string>

namespace dream::node::testing {

/// What a child run reported: "key=value" lines as a map.
using ChildReport = std::map<std::string, std::string>;

/// Runs `body` in a forked child whose files may not grow past `limit_bytes`
/// (RLIMIT_FSIZE) and which ignores SIGXFSZ, so a write past the limit fails
/// with EFBIG, exactly as under `ulimit -f` with the signal trapped. The limit
/// is exact and needs no privileges, so a disk "fills" at a chosen byte
/// without touching the test process. `body` reports through its map (gtest
/// assertions do not cross fork); files it writes stay for the caller to
/// check. A child that dies or throws reports "child_error".
inline ChildReport RunWithFileSizeLimit(rlim_t limit_bytes, const std::function<void(ChildReport*)>& body) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return {{"child_error", "pipe failed"}};
  const pid_t pid = ::fork();
  if (pid < 0) return {{"child_error", "fork failed"}};
  if (pid == 0) {
    ::close(pipe_fds[0]);
    ChildReport report;
    const rlimit limit{limit_bytes, limit_bytes};
    if (::signal(SIGXFSZ, SIG_IGN) == SIG_ERR || ::setrlimit(RLIMIT_FSIZE, &limit) != 0) {
      report["child_error"] = "cannot set the file size limit";
    } else {
      try {
        body(&report);
      } catch (const std::exception& e) {
        report["child_error"] = std::string("exception: ") + e.what();
      }
    }
    std::string text;
    for (const auto& [key, value] : report) text += key + "=" + value + "\n";
    const ssize_t written = ::write(pipe_fds[1], text.data(), text.size());
    ::_exit(written == static_cast<ssize_t>(text.size()) ? 0 : 1);  // no gtest teardown in the child
  }
  ::close(pipe_fds[1]);
  std::string text;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<size_t>(n));
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ChildReport report;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const size_t equals = line.find('=');
    if (equals != std::string::npos) report[line.substr(0, equals)] = line.substr(equals + 1);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) report["child_error"] += " (child exited abnormally)";
  return report;
}

}  // namespace dream::node::testing
