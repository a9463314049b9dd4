#pragma once

#include <cstdint>
#include <vector>

#include "dream/lcm/drawn_shape.h"

namespace dream::run_log {

/// What one robot's controller drew, as a run's log holds it (a drawing_t on
/// DREAM_DRAW_<id>, checked by lcm::DrawingShapes): shown from `step` until
/// the robot's next drawing.
struct RecordedDrawing {
  int64_t step = 0;
  int32_t robot_id = 0;
  int32_t clipped = 0;  ///< what the controller drew past the bounds that step, left out by its agent
  std::vector<lcm::DrawnShape> shapes;
};

/// Of `drawings` (ordered by step, as RunLog::drawings()), each robot's latest
/// at or before `step` that has shapes: what a picture of `step` shows. Pointers
/// into `drawings`, by robot.
std::vector<const RecordedDrawing*> DrawingsShownAt(const std::vector<RecordedDrawing>& drawings, int64_t step);

}  // namespace dream::run_log
