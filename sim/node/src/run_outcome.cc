#include "dream/node/run_outcome.h"

namespace dream::node {

const char* EndName(RunOutcome::End end) {
  switch (end) {
    case RunOutcome::End::kFinished:
      return "finished";
    case RunOutcome::End::kInterrupted:
      return "interrupted";
    case RunOutcome::End::kStartTimeout:
      return "start_timeout";
    case RunOutcome::End::kFailed:
      return "failed";
  }
  return "unknown";
}

}  // namespace dream::node
