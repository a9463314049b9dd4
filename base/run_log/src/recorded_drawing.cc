#include "dream/run_log/recorded_drawing.h"

#include <map>

namespace dream::run_log {

std::vector<const RecordedDrawing*> DrawingsShownAt(const std::vector<RecordedDrawing>& drawings, int64_t step) {
  std::map<int32_t, const RecordedDrawing*> latest;
  for (const RecordedDrawing& drawing : drawings) {
    if (drawing.step > step) break;
    latest[drawing.robot_id] = &drawing;
  }
  std::vector<const RecordedDrawing*> shown;
  for (const auto& [robot, drawing] : latest) {
    if (!drawing->shapes.empty()) shown.push_back(drawing);
  }
  return shown;
}

}  // namespace dream::run_log
