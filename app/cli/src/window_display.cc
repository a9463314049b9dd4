#include "window_display.h"

#include <cstdlib>
#include <stdexcept>

namespace dream::cli {
namespace {

bool IsSet(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && value[0] != '\0';
}

}  // namespace

void RequireWindowDisplay(const std::string& window, const std::string& instead) {
  if (IsSet("DISPLAY") || IsSet("WAYLAND_DISPLAY")) return;
  throw std::runtime_error(window +
                           " is a window, and there is no display here (DISPLAY and WAYLAND_DISPLAY are unset): " +
                           "run it in a desktop session or over ssh -X; " + instead);
}

}  // namespace dream::cli
