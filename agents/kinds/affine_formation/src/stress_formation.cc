#include "dream/affine_formation/stress_formation.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/params_check.h"

namespace dream::affine_formation {
namespace {

std::vector<int> FollowersOf(int n, const std::vector<int>& leaders) {
  std::vector<int> followers;
  for (int i = 0; i < n; ++i) {
    if (std::find(leaders.begin(), leaders.end(), i) == leaders.end()) followers.push_back(i);
  }
  return followers;
}

// -Omega_ff^-1 Omega_fl p_l, or nothing when Omega_ff is not positive definite.
std::optional<Eigen::MatrixXd> SolveFollowers(const Eigen::MatrixXd& omega, const std::vector<int>& followers,
                                              const std::vector<int>& leaders,
                                              const std::vector<Eigen::Vector2d>& positions) {
  const auto nf = static_cast<Eigen::Index>(followers.size());
  const auto nl = static_cast<Eigen::Index>(leaders.size());
  Eigen::MatrixXd off(nf, nf);
  Eigen::MatrixXd ofl(nf, nl);
  Eigen::MatrixXd pl(nl, 2);
  for (Eigen::Index a = 0; a < nf; ++a) {
    for (Eigen::Index b = 0; b < nf; ++b) off(a, b) = omega(followers[size_t(a)], followers[size_t(b)]);
    for (Eigen::Index b = 0; b < nl; ++b) ofl(a, b) = omega(followers[size_t(a)], leaders[size_t(b)]);
  }
  for (Eigen::Index b = 0; b < nl; ++b) pl.row(b) = positions[size_t(leaders[size_t(b)])].transpose();
  const Eigen::LLT<Eigen::MatrixXd> llt(off);
  if (llt.info() != Eigen::Success) return std::nullopt;
  return Eigen::MatrixXd(-llt.solve(ofl * pl));
}

Eigen::MatrixXd Omega(const Eigen::MatrixXd& w) {
  Eigen::MatrixXd omega = -w;
  for (Eigen::Index i = 0; i < w.rows(); ++i) omega(i, i) = w.row(i).sum();
  return omega;
}

// Each entry finite, the diagonal zero, the matrix symmetric.
bool CheckWeightEntries(const Eigen::MatrixXd& weights, std::string* error) {
  const Eigen::Index n = weights.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::string entry = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
      if (!std::isfinite(weights(i, j))) return agents::FailParams(error, "weights: entry " + entry + " is not finite");
      if (i == j && weights(i, j) != 0.0)
        return agents::FailParams(error, "weights: diagonal entry " + entry + " must be 0");
      if (std::abs(weights(i, j) - weights(j, i)) > 1e-9 * (1.0 + std::abs(weights(i, j)))) {
        return agents::FailParams(error, "weights: a stress is symmetric, but entry " + entry + " is " +
                                             agents::NumberText(weights(i, j)) + " and its transpose is " +
                                             agents::NumberText(weights(j, i)));
      }
    }
  }
  return true;
}

// Each point finite and no two at the same place.
bool CheckNominalPoints(const std::vector<Eigen::Vector2d>& nominal_m, std::string* error) {
  const auto n = static_cast<Eigen::Index>(nominal_m.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!nominal_m[size_t(i)].allFinite())
      return agents::FailParams(error, "nominal_m: point " + std::to_string(i) + " is not finite");
    for (Eigen::Index j = 0; j < i; ++j) {
      if ((nominal_m[size_t(i)] - nominal_m[size_t(j)]).norm() < 1e-9) {
        return agents::FailParams(error,
                                  "nominal_m: points " + std::to_string(j) + " and " + std::to_string(i) + " coincide");
      }
    }
  }
  return true;
}

}  // namespace

bool StressFormationParams::IsValid(std::string* error) const {
  const auto n = static_cast<Eigen::Index>(nominal_m.size());
  if (n < 4)
    return agents::FailParams(error,
                              "nominal_m: need at least 4 robots (3 leaders and a follower), got " + std::to_string(n));
  if (weights.rows() != n || weights.cols() != n) {
    return agents::FailParams(error, "weights: must be " + std::to_string(n) + "x" + std::to_string(n) +
                                         " (one row and column per robot), got " + std::to_string(weights.rows()) +
                                         "x" + std::to_string(weights.cols()));
  }
  if (!CheckWeightEntries(weights, error) || !CheckNominalPoints(nominal_m, error)) return false;
  if (leaders.size() < 3) {
    return agents::FailParams(
        error, "leaders: a planar affine formation needs at least 3 leaders, got " + std::to_string(leaders.size()));
  }
  std::vector<Eigen::Vector2d> leader_points;
  for (size_t k = 0; k < leaders.size(); ++k) {
    if (leaders[k] < 0 || leaders[k] >= n) {
      return agents::FailParams(
          error, "leaders: id " + std::to_string(leaders[k]) + " is not a robot (0.." + std::to_string(n - 1) + ")");
    }
    if (std::count(leaders.begin(), leaders.end(), leaders[k]) > 1) {
      return agents::FailParams(error, "leaders: id " + std::to_string(leaders[k]) + " is listed twice");
    }
    leader_points.push_back(nominal_m[size_t(leaders[k])]);
  }
  if (!agents::AffineTransform::Fit(leader_points, leader_points)) {
    return agents::FailParams(error,
                              "leaders: their nominal points are collinear, so they cannot define an affine map");
  }
  const std::vector<int> followers = FollowersOf(static_cast<int>(n), leaders);
  if (followers.empty())
    return agents::FailParams(error, "leaders: every robot is a leader; there is no follower to control");
  for (int f : followers) {
    const double gamma = weights.row(f).sum();
    if (!(gamma > 0.0)) {
      return agents::FailParams(error, "weights: follower " + std::to_string(f) + "'s weights sum to " +
                                           agents::NumberText(gamma) +
                                           "; the normalised follower law divides by that sum, which must be > 0");
    }
  }
  if (!(equilibrium_tolerance_m > 0.0) || !std::isfinite(equilibrium_tolerance_m)) {
    return agents::FailParams(
        error, "equilibrium_tolerance_m: must be > 0, got " + agents::NumberText(equilibrium_tolerance_m));
  }
  const Eigen::MatrixXd omega = Omega(weights);
  const std::optional<Eigen::MatrixXd> settled = SolveFollowers(omega, followers, leaders, nominal_m);
  if (!settled) {
    return agents::FailParams(
        error,
        "weights: the followers' block of the stress matrix is not positive definite, so the followers "
        "have no unique stable target (Zhao 2018, Lemma 1)");
  }
  for (size_t a = 0; a < followers.size(); ++a) {
    const Eigen::Vector2d target = settled->row(Eigen::Index(a)).transpose();
    const double off_m = (target - nominal_m[size_t(followers[a])]).norm();
    if (off_m > equilibrium_tolerance_m) {
      return agents::FailParams(
          error, "weights: not an equilibrium stress of nominal_m: follower " + std::to_string(followers[a]) +
                     " would settle " + agents::NumberText(off_m) + " m from its nominal point (tolerance " +
                     agents::NumberText(equilibrium_tolerance_m) + " m); check sum_j w_ij (r_i - r_j) = 0");
    }
  }
  return true;
}

StressFormation::StressFormation(StressFormationParams params) : params_(std::move(params)) {
  std::string error;
  if (!params_.IsValid(&error)) throw std::invalid_argument(error);
  followers_ = FollowersOf(size(), params_.leaders);
}

bool StressFormation::IsLeader(int id) const {
  return std::find(params_.leaders.begin(), params_.leaders.end(), id) != params_.leaders.end();
}

std::vector<std::pair<int, double>> StressFormation::Neighbours(int i) const {
  std::vector<std::pair<int, double>> neighbours;
  for (int j = 0; j < size(); ++j) {
    if (params_.weights(i, j) != 0.0) neighbours.emplace_back(j, params_.weights(i, j));
  }
  return neighbours;
}

double StressFormation::Gamma(int i) const { return params_.weights.row(i).sum(); }

Eigen::MatrixXd StressFormation::StressMatrix() const { return Omega(params_.weights); }

Eigen::Vector2d StressFormation::StressResidual(int i, const std::vector<Eigen::Vector2d>& positions_m) const {
  Eigen::Vector2d residual = Eigen::Vector2d::Zero();
  for (int j = 0; j < size(); ++j) {
    residual += params_.weights(i, j) * (positions_m.at(size_t(i)) - positions_m.at(size_t(j)));
  }
  return residual;
}

std::vector<Eigen::Vector2d> StressFormation::FollowerEquilibrium(
    const std::vector<Eigen::Vector2d>& positions_m) const {
  if (positions_m.size() != params_.nominal_m.size()) {
    throw std::invalid_argument("FollowerEquilibrium: expected " + std::to_string(size()) + " positions, got " +
                                std::to_string(positions_m.size()));
  }
  std::vector<Eigen::Vector2d> result = positions_m;
  // Positive definite was checked at construction.
  const Eigen::MatrixXd settled = *SolveFollowers(StressMatrix(), followers_, params_.leaders, positions_m);
  for (size_t a = 0; a < followers_.size(); ++a)
    result[size_t(followers_[a])] = settled.row(Eigen::Index(a)).transpose();
  return result;
}

std::optional<agents::AffineTransform> StressFormation::LeaderTransform(
    const std::vector<Eigen::Vector2d>& positions_m) const {
  std::vector<Eigen::Vector2d> from;
  std::vector<Eigen::Vector2d> to;
  for (int id : params_.leaders) {
    if (size_t(id) >= positions_m.size()) return std::nullopt;
    from.push_back(params_.nominal_m[size_t(id)]);
    to.push_back(positions_m[size_t(id)]);
  }
  return agents::AffineTransform::Fit(from, to);
}

}  // namespace dream::affine_formation
