#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dream/agents/geometry/affine_transform.h"

namespace dream::affine_formation {

/// What defines an affine formation (Zhao 2018, "Affine Formation Maneuver
/// Control of Multiagent Systems", IEEE TAC 63(12)): symmetric edge weights
/// w_ij (zero diagonal; zero = no link), the nominal configuration r_i, and
/// which robots lead.
struct StressFormationParams {
  Eigen::MatrixXd weights;                 ///< n x n, finite, symmetric, zero diagonal
  std::vector<Eigen::Vector2d> nominal_m;  ///< one r_i per robot, metres, pairwise distinct
  std::vector<int> leaders;                ///< distinct ids; their nominal points must not be collinear
  /// How far a follower's stress equilibrium (given the leaders at their
  /// nominal points) may lie from its nominal point, m: the weights must be
  /// an equilibrium stress of the nominal configuration, up to rounding (the
  /// thesis prints them to 4 decimals, which moves the equilibrium < 1 mm).
  double equilibrium_tolerance_m = 0.005;

  /// False with a message that starts with the field at fault (weights,
  /// nominal_m, leaders, equilibrium_tolerance_m) and says what is wrong.
  bool IsValid(std::string* error) const;
};

/// An affine formation: the stress matrix Omega (Omega_ij = -w_ij,
/// Omega_ii = sum_j w_ij) of a nominal configuration, split into leaders and
/// followers. Followers in stress equilibrium, sum_j w_ij (p_i - p_j) = 0,
/// sit exactly at the affine image of their nominal points defined by the
/// leaders (Zhao 2018, Theorem 1), whatever affine map the leaders realise.
class StressFormation {
 public:
  /// @throws std::invalid_argument with IsValid()'s message.
  explicit StressFormation(StressFormationParams params);

  int size() const { return static_cast<int>(params_.nominal_m.size()); }
  const std::vector<int>& leaders() const { return params_.leaders; }
  const std::vector<int>& followers() const { return followers_; }
  bool IsLeader(int id) const;
  const std::vector<Eigen::Vector2d>& nominal_m() const { return params_.nominal_m; }
  double Weight(int i, int j) const { return params_.weights(i, j); }

  /// Robot i's neighbours (non-zero weights) as (id, w_ij), by id.
  std::vector<std::pair<int, double>> Neighbours(int i) const;
  /// gamma_i = sum_j w_ij, the normaliser of Zhao's follower law.
  double Gamma(int i) const;
  /// Omega.
  Eigen::MatrixXd StressMatrix() const;
  /// sum_j w_ij (p_i - p_j) for robot i; zero for a follower in equilibrium.
  Eigen::Vector2d StressResidual(int i, const std::vector<Eigen::Vector2d>& positions_m) const;

  /// Where the followers settle when every one is in stress equilibrium with
  /// the leaders at `positions_m` (followers' entries ignored): indexed like
  /// positions_m, leaders' entries copied. -Omega_ff^-1 Omega_fl p_l.
  std::vector<Eigen::Vector2d> FollowerEquilibrium(const std::vector<Eigen::Vector2d>& positions_m) const;

  /// The affine map that takes the leaders' nominal points to their entries
  /// of `positions_m` (least squares when there are more than three leaders);
  /// nothing when those entries are collinear or not finite.
  std::optional<agents::AffineTransform> LeaderTransform(const std::vector<Eigen::Vector2d>& positions_m) const;

 private:
  StressFormationParams params_;
  std::vector<int> followers_;
};

}  // namespace dream::affine_formation
