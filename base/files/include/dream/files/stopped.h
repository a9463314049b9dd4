#pragma once

#include <stdexcept>

namespace dream::files {

/// Thrown where a computation saw its StopToken requested: unwinding past
/// every writer, so a stopped command leaves no output; the command line
/// turns it into exit 130.
class Stopped : public std::runtime_error {
 public:
  Stopped() : std::runtime_error("interrupted (Ctrl-C or SIGTERM); nothing written") {}
};

}  // namespace dream::files
