#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace dream::line_deployment {

/// A neighbour's position as its radio reported it.
struct NeighbourPosition {
  int id = 0;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
};

/// The thesis's eq. 3.7 (line deployment by consensus): robot `self_id`'s
/// next target from its neighbours j,
///     P_ix = mean_j (P_jx + (id_j - id_i) d),   P_iy = mean_j P_jy,
/// so at consensus (connected graph) the robots stand on one horizontal line
/// `spacing_m` apart, at x_i = c - id_i d: as printed, the sign puts robot 0
/// rightmost and ids descend along x. Nothing when there are no neighbours.
std::optional<Eigen::Vector2d> LineConsensusTarget(int self_id, const std::vector<NeighbourPosition>& neighbours,
                                                   double spacing_m);

}  // namespace dream::line_deployment
