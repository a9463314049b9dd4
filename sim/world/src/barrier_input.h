#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dream/world/pose2.h"
#include "dream/world/unicycle_command.h"

namespace dream::world {

/// The certificate's input from the world's types: every robot's wanted command (v; w) and pose
/// (x; y; theta) as the 2 x N and 3 x N columns barriers::UnicycleBarrier::Apply takes. The
/// start-up drive and BarrierWorld fill theirs the same way, here.
inline void FillBarrierInput(const std::vector<UnicycleCommand>& commands, const std::vector<Pose2>& poses,
                             Eigen::Matrix2Xd* wanted, Eigen::Matrix3Xd* pose_matrix) {
  const Eigen::Index n = static_cast<Eigen::Index>(poses.size());
  wanted->resize(2, n);
  pose_matrix->resize(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    (*wanted)(0, k) = commands[i].v_mps;
    (*wanted)(1, k) = commands[i].w_radps;
    (*pose_matrix)(0, k) = poses[i].x_m;
    (*pose_matrix)(1, k) = poses[i].y_m;
    (*pose_matrix)(2, k) = poses[i].theta_rad;
  }
}

}  // namespace dream::world
