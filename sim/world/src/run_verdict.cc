#include "dream/world/run_verdict.h"

namespace dream::world {

const char* RunVerdictName(RunVerdict verdict) {
  switch (verdict) {
    case RunVerdict::kClean:
      return "clean";
    case RunVerdict::kWarning:
      return "warning";
    case RunVerdict::kNotReady:
      return "not_ready";
    case RunVerdict::kRejected:
      return "rejected";
  }
  return "unknown";
}

std::optional<RunVerdict> ParseRunVerdict(const std::string& name) {
  for (RunVerdict verdict : {RunVerdict::kClean, RunVerdict::kWarning, RunVerdict::kNotReady, RunVerdict::kRejected}) {
    if (name == RunVerdictName(verdict)) return verdict;
  }
  return std::nullopt;
}

}  // namespace dream::world
