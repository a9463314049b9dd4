#pragma once

#include <vector>

#include <Eigen/Core>

namespace dream::barriers {

/// The constraints G x <= h of a barrier QP. The unknowns come in pairs, one
/// robot's velocity (x[2k], x[2k+1]), and a row touches one robot (a wall, a
/// side of the speed octagon) or two (a pair): so a row is one or two 2-column
/// blocks, and the solver's G' D G costs a few products per row instead of a
/// dense n x n per row.
class LinearInequalities {
 public:
  static constexpr int kNoBlock = -1;

  explicit LinearInequalities(int num_blocks = 0) { Reset(num_blocks); }

  /// Starts again with no rows, keeping the storage (one solver per run, a QP per step).
  void Reset(int num_blocks);
  /// Appends `a0 x[2a] + a1 x[2a+1] <= bound` (a row of one robot).
  /// @throws std::out_of_range for a block outside [0, num_blocks).
  void AddRow(int block_a, double a0, double a1, double bound);
  /// Appends `a0 x[2a] + a1 x[2a+1] + b0 x[2b] + b1 x[2b+1] <= bound`, a < b.
  /// @throws std::out_of_range unless 0 <= a < b < num_blocks.
  void AddRow(int block_a, double a0, double a1, int block_b, double b0, double b1, double bound);

  int num_blocks() const { return num_blocks_; }
  int num_variables() const { return 2 * num_blocks_; }
  int num_rows() const { return static_cast<int>(bounds_.size()); }
  int block_a(int row) const { return block_a_[static_cast<size_t>(row)]; }
  /// kNoBlock for a row of one robot.
  int block_b(int row) const { return block_b_[static_cast<size_t>(row)]; }
  /// The row's coefficients: a0, a1, b0, b1.
  const double* coefficients(int row) const { return &coefficients_[4 * static_cast<size_t>(row)]; }
  double bound(int row) const { return bounds_[static_cast<size_t>(row)]; }
  const std::vector<double>& bounds() const { return bounds_; }

  /// out = G x.
  void Multiply(const Eigen::VectorXd& x, Eigen::VectorXd* out) const;
  /// out = G' y.
  void MultiplyTransposed(const Eigen::VectorXd& y, Eigen::VectorXd* out) const;
  /// A dense copy of G (tests, diagnostics).
  Eigen::MatrixXd Dense() const;

 private:
  int num_blocks_ = 0;
  std::vector<int> block_a_;
  std::vector<int> block_b_;
  std::vector<double> coefficients_;
  std::vector<double> bounds_;
};

}  // namespace dream::barriers
