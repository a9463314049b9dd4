#pragma once

namespace dream::sim {

// A unicycle velocity command: forward speed and turn rate.
struct UnicycleCommand {
  double v_mps = 0.0;
  double w_radps = 0.0;
};

}  // namespace dream::sim
