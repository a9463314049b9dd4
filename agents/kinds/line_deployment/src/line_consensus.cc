#include "dream/line_deployment/line_consensus.h"

namespace dream::line_deployment {

std::optional<Eigen::Vector2d> LineConsensusTarget(int self_id, const std::vector<NeighbourPosition>& neighbours,
                                                   double spacing_m) {
  if (neighbours.empty()) return std::nullopt;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const NeighbourPosition& n : neighbours) {
    sum += n.position_m + Eigen::Vector2d(static_cast<double>(n.id - self_id) * spacing_m, 0.0);
  }
  return Eigen::Vector2d(sum / static_cast<double>(neighbours.size()));
}

}  // namespace dream::line_deployment
