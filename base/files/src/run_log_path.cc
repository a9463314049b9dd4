#include "dream/files/run_log_path.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace dream::files {

std::string RunLogPath(const std::string& run_or_log) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::exists(run_or_log, error)) {
    throw std::runtime_error(run_or_log +
                             ": no such file or folder; give a run folder (runs/<name>) or its run.lcmlog");
  }
  if (!fs::is_directory(run_or_log, error)) return run_or_log;
  const std::string log = (fs::path(run_or_log) / "run.lcmlog").string();
  if (!fs::is_regular_file(log, error)) {
    throw std::runtime_error(log + " is missing (no such log file): " + run_or_log +
                             " is not a run folder written by dream run (or its log was not finished: a "
                             "run.lcmlog.part is renamed when the run ends)");
  }
  return log;
}

}  // namespace dream::files
