#pragma once

#include <initializer_list>
#include <vector>

#include <Eigen/Core>

namespace dream::barriers {

/// The constraints G x <= h of a QP, G stored by rows with only its nonzeros:
/// a barrier's rows touch two robots at most (four columns), so the solver's
/// G' D G costs a few products per row instead of a dense n x n per row.
class LinearInequalities {
 public:
  explicit LinearInequalities(int num_variables = 0) : num_variables_(num_variables) { row_start_.push_back(0); }

  /// Starts again with no rows, keeping the storage (one solver per run, a QP per step).
  void Reset(int num_variables);
  /// Appends the row `sum_k values[k] x[columns[k]] <= bound`.
  void AddRow(std::initializer_list<int> columns, std::initializer_list<double> values, double bound);

  int num_variables() const { return num_variables_; }
  int num_rows() const { return static_cast<int>(bounds_.size()); }
  int row_begin(int row) const { return row_start_[static_cast<size_t>(row)]; }
  int row_end(int row) const { return row_start_[static_cast<size_t>(row) + 1]; }
  int column(int entry) const { return columns_[static_cast<size_t>(entry)]; }
  double value(int entry) const { return values_[static_cast<size_t>(entry)]; }
  double bound(int row) const { return bounds_[static_cast<size_t>(row)]; }
  const std::vector<double>& bounds() const { return bounds_; }

  /// out = G x.
  void Multiply(const Eigen::VectorXd& x, Eigen::VectorXd* out) const;
  /// out = G' y.
  void MultiplyTransposed(const Eigen::VectorXd& y, Eigen::VectorXd* out) const;
  /// A dense copy of G (tests, diagnostics).
  Eigen::MatrixXd Dense() const;

 private:
  int num_variables_ = 0;
  std::vector<int> row_start_;
  std::vector<int> columns_;
  std::vector<double> values_;
  std::vector<double> bounds_;
};

}  // namespace dream::barriers
