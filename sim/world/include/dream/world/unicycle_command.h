#pragma once

namespace dream::world {

// A unicycle velocity command: forward speed and turn rate.
struct UnicycleCommand {
  double v_mps = 0.0;    ///< forward speed along the heading, m/s; negative drives backwards
  double w_radps = 0.0;  ///< turn rate, rad/s, counter-clockwise positive (as theta grows)
};

}  // namespace dream::world
