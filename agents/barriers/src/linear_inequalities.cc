#include "dream/barriers/linear_inequalities.h"

#include <stdexcept>
#include <string>

namespace dream::barriers {

void LinearInequalities::Reset(int num_blocks) {
  num_blocks_ = num_blocks;
  block_a_.clear();
  block_b_.clear();
  coefficients_.clear();
  bounds_.clear();
}

void LinearInequalities::AddRow(int block_a, double a0, double a1, double bound) {
  if (block_a < 0 || block_a >= num_blocks_) {
    throw std::out_of_range("LinearInequalities: block " + std::to_string(block_a) + " outside [0, " +
                            std::to_string(num_blocks_) + ")");
  }
  block_a_.push_back(block_a);
  block_b_.push_back(kNoBlock);
  coefficients_.insert(coefficients_.end(), {a0, a1, 0.0, 0.0});
  bounds_.push_back(bound);
}

void LinearInequalities::AddRow(int block_a, double a0, double a1, int block_b, double b0, double b1, double bound) {
  if (block_a < 0 || block_b <= block_a || block_b >= num_blocks_) {
    throw std::out_of_range("LinearInequalities: blocks " + std::to_string(block_a) + ", " + std::to_string(block_b) +
                            " are not ascending in [0, " + std::to_string(num_blocks_) + ")");
  }
  block_a_.push_back(block_a);
  block_b_.push_back(block_b);
  coefficients_.insert(coefficients_.end(), {a0, a1, b0, b1});
  bounds_.push_back(bound);
}

void LinearInequalities::Multiply(const Eigen::VectorXd& x, Eigen::VectorXd* out) const {
  out->resize(num_rows());
  const double* v = x.data();
  for (int row = 0; row < num_rows(); ++row) {
    const double* c = coefficients(row);
    const int a = 2 * block_a(row);
    double sum = c[0] * v[a] + c[1] * v[a + 1];
    const int b = block_b(row);
    if (b != kNoBlock) sum += c[2] * v[2 * b] + c[3] * v[2 * b + 1];
    (*out)[row] = sum;
  }
}

void LinearInequalities::MultiplyTransposed(const Eigen::VectorXd& y, Eigen::VectorXd* out) const {
  out->setZero(num_variables());
  double* v = out->data();
  // Rows come in runs of one first block (rps's pairs (i, j > i), then each robot's walls and
  // octagon): its two sums stay in registers over the run instead of a store and load per row.
  int run = kNoBlock;
  double sum0 = 0.0, sum1 = 0.0;
  for (int row = 0; row < num_rows(); ++row) {
    const double* c = coefficients(row);
    const int a = block_a(row);
    if (a != run) {
      if (run != kNoBlock) {
        v[2 * run] += sum0;
        v[2 * run + 1] += sum1;
      }
      run = a;
      sum0 = sum1 = 0.0;
    }
    sum0 += c[0] * y[row];
    sum1 += c[1] * y[row];
    const int b = block_b(row);
    if (b != kNoBlock) {
      v[2 * b] += c[2] * y[row];
      v[2 * b + 1] += c[3] * y[row];
    }
  }
  if (run != kNoBlock) {
    v[2 * run] += sum0;
    v[2 * run + 1] += sum1;
  }
}

Eigen::MatrixXd LinearInequalities::Dense() const {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(num_rows(), num_variables());
  for (int row = 0; row < num_rows(); ++row) {
    const double* c = coefficients(row);
    dense(row, 2 * block_a(row)) = c[0];
    dense(row, 2 * block_a(row) + 1) = c[1];
    if (block_b(row) != kNoBlock) {
      dense(row, 2 * block_b(row)) = c[2];
      dense(row, 2 * block_b(row) + 1) = c[3];
    }
  }
  return dense;
}

}  // namespace dream::barriers
