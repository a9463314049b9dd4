#pragma once

namespace dream::world {

// Angular speeds of a differential-drive robot's two wheels.
struct WheelSpeeds {
  double left_radps = 0.0;
  double right_radps = 0.0;
};

}  // namespace dream::world
