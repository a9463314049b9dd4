#include "lcm_java_tools.h"

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "dream/process/data_files.h"
#include "dream/process/process_group.h"
#include "dream/workflows/shell_quoted.h"

namespace dream::cli {

std::string RequireToolFile(const std::string& path, const char* what, const char* hint) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(std::string(what) + " " + path + " is missing: " + hint);
  return path;
}

std::string RequireLcmJar() { return RequireToolFile(DREAM_LCM_JAR, "lcm.jar", "apt-get install liblcm-java"); }

std::string SpyClasspath() {
  std::string types_jar = process::DataFiles::TypesJar();
  if (const char* env = std::getenv("DREAM_TYPES_JAR"); env != nullptr && std::filesystem::exists(env)) {
    types_jar = env;
  }
  return RequireLcmJar() + ":" +
         RequireToolFile("/usr/share/java/jchart2d.jar", "jchart2d.jar", "apt-get install libjchart2d-java") + ":" +
         RequireToolFile(types_jar, "the types jar",
                         "build the project (cmake --build) or set DREAM_TYPES_JAR to dream_lcmtypes.jar");
}

void PrintToolCommands(const std::vector<std::vector<std::string>>& commands) {
  for (const std::vector<std::string>& command : commands) {
    if (!command.empty()) std::cout << workflows::ShellCommandLine(command) << '\n';
  }
}

int RunToolsUntilClosed(const std::vector<std::vector<std::string>>& commands, size_t wait_for, unsigned pause_s) {
  process::ProcessGroup children;
  pid_t waited = -1;
  bool started_one = false;
  for (size_t i = 0; i < commands.size(); ++i) {
    if (commands[i].empty()) continue;
    if (started_one && pause_s > 0) sleep(pause_s);  // Ctrl-C cuts it short
    if (StopFlag().load()) break;
    const pid_t pid = children.Start(commands[i]);
    started_one = true;
    if (i == wait_for) waited = pid;
  }
  if (StopFlag().load()) return kExitInterrupted;  // the group ends what started
  if (waited < 0) throw std::logic_error("RunToolsUntilClosed: the command to wait for is empty");
  const int code = children.WaitPassingOnStop(waited, StopFlag(), SIGTERM);
  if (StopFlag().load()) return kExitInterrupted;
  return code == 0 ? kExitOk : kExitRunFailed;
}

}  // namespace dream::cli
