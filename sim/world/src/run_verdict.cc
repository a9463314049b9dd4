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

}  // namespace dream::world
