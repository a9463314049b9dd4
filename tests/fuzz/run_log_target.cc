#include <cstdint>
#include <exception>
#include <filesystem>

#include "dream/run_log/run_log.h"
#include "fuzz_targets.h"

namespace dream::fuzz {

void RunLogTarget(const uint8_t* data, size_t size) {
  const std::string path = ScratchFile(data, size, ".lcmlog");
  try {
    const run_log::RunLog log = run_log::RunLog::Read(path);
    (void)log.Flaw(true);
    (void)log.Flaw(false);
    for (size_t i = 0; i < log.poses().size(); ++i) (void)log.obstacles_at(i);
    (void)log.PoseIndexAtStep(log.last_step());
    (void)log.PoseIndexAtStep(INT64_MIN);
    (void)log.PoseIndexAtStep(INT64_MAX);
  } catch (const std::exception& e) {
    if (std::string(e.what()).find(path) == std::string::npos)
      Finding("a run log error without its file: " + std::string(e.what()));
  }
  std::filesystem::remove(path);
}

}  // namespace dream::fuzz
