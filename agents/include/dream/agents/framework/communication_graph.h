#pragma once

#include <Eigen/Core>
#include <string>

namespace dream::agents {

/// Who may talk to whom: a square adjacency (or weight) matrix; robot i hears
/// robot j when entry (i, j) is non-zero.
class CommunicationGraph {
 public:
  /// @param require_symmetric links must go both ways (consensus needs it).
  /// @param require_connected every robot must reach every other.
  /// @throws std::invalid_argument naming the problem (size, entry, asymmetry,
  ///         unreachable robot) otherwise.
  CommunicationGraph(Eigen::MatrixXd adjacency, int num_robots, bool require_symmetric, bool require_connected);

  bool Linked(int from, int to) const { return adjacency_(to, from) != 0.0; }
  double Weight(int i, int j) const { return adjacency_(i, j); }
  int size() const { return static_cast<int>(adjacency_.rows()); }
  const Eigen::MatrixXd& matrix() const { return adjacency_; }

 private:
  Eigen::MatrixXd adjacency_;
};

}  // namespace dream::agents
