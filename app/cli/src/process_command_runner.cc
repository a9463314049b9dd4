#include "process_command_runner.h"

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <fstream>

#include "dream/process/process_group.h"

namespace dream::cli {
namespace {

constexpr size_t kMaxOutputBytes = size_t{4} << 20;

}  // namespace

workflows::CommandRunner::Result ProcessCommandRunner::Run(const std::vector<std::string>& argv) {
  Result result;
  const char* tmp = std::getenv("TMPDIR");
  std::string path = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/dream-command-XXXXXX";
  const int fd = ::mkstemp(path.data());
  if (fd < 0) {
    result.output = "cannot make a temporary file in " + path;
    return result;
  }
  ::close(fd);
  try {
    process::ProcessGroup group;
    const pid_t pid = group.Start(argv, path);
    result.exit_code = group.WaitFor(pid, timeout_s_);
    if (result.exit_code < 0) {
      group.SignalAll(SIGKILL);
      group.Wait(pid);
      result.exit_code = 124;
      result.output = argv[0] + " did not answer within " + std::to_string(static_cast<int>(timeout_s_)) + " s\n";
    }
  } catch (const std::exception& e) {
    ::unlink(path.c_str());
    result.exit_code = -1;
    result.output = e.what();
    return result;
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(kMaxOutputBytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(kMaxOutputBytes));
  text.resize(static_cast<size_t>(in.gcount()));
  result.output += text;
  ::unlink(path.c_str());
  return result;
}

}  // namespace dream::cli
