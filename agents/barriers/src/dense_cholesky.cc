#include "dream/barriers/dense_cholesky.h"

#include <cmath>

namespace dream::barriers {

void DenseCholesky::Reset(int n) {
  n_ = n;
  lower_.assign(static_cast<size_t>(n) * n, 0.0);
}

void DenseCholesky::AddDiagonal(const Eigen::VectorXd& values) {
  for (int i = 0; i < n_; ++i) lower_[static_cast<size_t>(i) * n_ + i] += values[i];
}

bool DenseCholesky::FactorColumn(size_t j) {
  const size_t n = static_cast<size_t>(n_);
  double* column_j = lower_.data() + j * n;
  const double diagonal = column_j[j];
  if (!(diagonal > 0.0) || !std::isfinite(diagonal)) return false;
  const double pivot = std::sqrt(diagonal);
  column_j[j] = pivot;
  const double inverse = 1.0 / pivot;
  for (size_t i = j + 1; i < n; ++i) column_j[i] *= inverse;
  return true;
}

bool DenseCholesky::Factor() {
  double* a = lower_.data();
  const size_t n = static_cast<size_t>(n_);
  size_t j = 0;
  // Two columns at a time: the trailing triangle is read and written once per pair.
  for (; j + 1 < n; j += 2) {
    if (!FactorColumn(j)) return false;
    const double* column_j = a + j * n;
    double* column_j1 = a + (j + 1) * n;
    const double f = column_j[j + 1];
    for (size_t i = j + 1; i < n; ++i) column_j1[i] -= f * column_j[i];
    if (!FactorColumn(j + 1)) return false;
    for (size_t k = j + 2; k < n; ++k) {
      double* column_k = a + k * n;
      const double f0 = column_j[k];
      const double f1 = column_j1[k];
      for (size_t i = k; i < n; ++i) column_k[i] -= f0 * column_j[i] + f1 * column_j1[i];
    }
  }
  if (j < n && !FactorColumn(j)) return false;
  // L' by columns too, so the backward solve runs over contiguous memory.
  upper_.resize(n * n);  // only its upper triangle is written and read
  for (size_t c = 0; c < n; ++c) {
    for (size_t r = c; r < n; ++r) upper_[r * n + c] = a[c * n + r];
  }
  return true;
}

void DenseCholesky::SolveInPlace(Eigen::VectorXd* x) const {
  double* v = x->data();
  const size_t n = static_cast<size_t>(n_);
  const double* a = lower_.data();
  for (size_t j = 0; j < n; ++j) {  // L y = b, by columns of L
    const double* column_j = a + j * n;
    v[j] /= column_j[j];
    const double vj = v[j];
    for (size_t i = j + 1; i < n; ++i) v[i] -= column_j[i] * vj;
  }
  const double* u = upper_.data();
  for (size_t j = n; j-- > 0;) {  // L' x = y, by columns of L'
    const double* column_j = u + j * n;
    v[j] /= column_j[j];
    const double vj = v[j];
    for (size_t i = 0; i < j; ++i) v[i] -= column_j[i] * vj;
  }
}

}  // namespace dream::barriers
