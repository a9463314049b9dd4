#include "dream/agents/geometry/velocity_box.h"

namespace dream::agents {

VelocityBox VelocityBox::KeepingInside(const Eigen::Vector2d& arena_min_m, const Eigen::Vector2d& arena_max_m,
                                       const Eigen::Vector2d& position_m, double margin_m, double horizon_s,
                                       double inset_mps) {
  const double m = margin_m;
  const double h = horizon_s;
  VelocityBox box{Eigen::Vector2d((arena_min_m.x() + m - position_m.x()) / h + inset_mps,
                                  (arena_min_m.y() + m - position_m.y()) / h + inset_mps),
                  Eigen::Vector2d((arena_max_m.x() - m - position_m.x()) / h - inset_mps,
                                  (arena_max_m.y() - m - position_m.y()) / h - inset_mps)};
  box.lo = box.lo.cwiseMin(Eigen::Vector2d::Zero());
  box.hi = box.hi.cwiseMax(Eigen::Vector2d::Zero());
  return box;
}

}  // namespace dream::agents
