#pragma once

#include <Eigen/Core>

namespace dream::barriers {

/// What a barrier certificate gives for one step.
struct BarrierResult {
  /// The safe commands, one column per robot: single-integrator velocities
  /// (m/s) or unicycle commands (v m/s, w rad/s). All zeros when the QP failed.
  Eigen::Matrix2Xd commands;
  /// The QP did not end 'optimal' (iteration limit, singular system, NaN): the
  /// robots are told to stand still, as rps does ("QP failed. Commanding zero
  /// velocities").
  bool qp_failed = false;
  int qp_iterations = 0;
};

}  // namespace dream::barriers
