#pragma once

namespace dream::agents {

/// A differential-drive robot's command in unicycle form.
struct UnicycleCommand {
  double v_mps = 0.0;    ///< forward speed, m/s, body frame
  double w_radps = 0.0;  ///< turn rate, rad/s, counter-clockwise
};

}  // namespace dream::agents
