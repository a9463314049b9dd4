#include "dream/files/stop_token.h"

#include "dream/files/stopped.h"

namespace dream::files {

void StopToken::ThrowIfRequested() const {
  if (Requested()) throw Stopped();
}

}  // namespace dream::files
