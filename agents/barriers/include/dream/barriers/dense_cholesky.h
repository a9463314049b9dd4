#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace dream::barriers {

/// S = L L' for the small dense normal matrices of the barrier QP (40 x 40 at
/// 20 robots): the lower triangle stored by columns and factored
/// right-looking four columns at a time, L' kept by columns too, so every
/// inner loop is independent multiply-adds over contiguous memory the
/// compiler vectorizes. Eigen's LLT blocks at this size
/// and spends more in its GEMM kernels than in arithmetic (barrier_benchmark).
class DenseCholesky {
 public:
  /// An n x n zero matrix for Add*().
  void Reset(int n);
  /// S(row, column) += value, for row >= column.
  void AddLower(int row, int column, double value) { lower_[static_cast<size_t>(column) * n_ + row] += value; }
  void AddDiagonal(const Eigen::VectorXd& values);
  /// Factors in place; false when S is not (numerically) positive definite.
  bool Factor();
  /// x := S^-1 x.
  void SolveInPlace(Eigen::VectorXd* x) const;

 private:
  /// Column j's pivot and scaling; false when S is not positive definite there.
  bool FactorColumn(size_t j);
  /// Columns j to j + 3 factored and the trailing triangle updated by all four.
  bool FactorFourColumns(size_t j);

  int n_ = 0;
  std::vector<double> lower_;  ///< S, then L, by columns
  std::vector<double> upper_;  ///< L' by columns (row j of L in column j)
};

}  // namespace dream::barriers
