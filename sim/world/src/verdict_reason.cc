#include "dream/world/verdict_reason.h"

namespace dream::world {

std::string VerdictReason::Text() const {
  return rule + ": " + problem + (find_out.empty() ? "" : " (more: " + find_out + ")");
}

}  // namespace dream::world
