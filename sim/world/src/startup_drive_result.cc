#include "dream/world/startup_drive_result.h"

#include "dream/world/printf_text.h"

namespace dream::world {

std::string StartupDriveResult::DescribeMisses() const {
  if (!refusal.empty()) return refusal;
  std::string text;
  for (const Miss& miss : misses) {
    text += (text.empty() ? "" : ", ") +
            PrintfText("robot %d %.3f m / %.2f rad", miss.robot_id, miss.distance_m, miss.heading_error_rad);
  }
  return text;
}

}  // namespace dream::world
