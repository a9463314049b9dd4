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

bool DenseCholesky::Factor() {
  double* a = lower_.data();
  const size_t n = static_cast<size_t>(n_);
  for (size_t j = 0; j < n; ++j) {
    double* column_j = a + j * n;
    const double diagonal = column_j[j];
    if (!(diagonal > 0.0) || !std::isfinite(diagonal)) return false;
    const double pivot = std::sqrt(diagonal);
    column_j[j] = pivot;
    const double inverse = 1.0 / pivot;
    for (size_t i = j + 1; i < n; ++i) column_j[i] *= inverse;
    for (size_t k = j + 1; k < n; ++k) {  // the trailing lower triangle -= l_j l_j'
      double* column_k = a + k * n;
      const double factor = column_j[k];
      for (size_t i = k; i < n; ++i) column_k[i] -= factor * column_j[i];
    }
  }
  return true;
}

void DenseCholesky::SolveInPlace(Eigen::VectorXd* x) const {
  double* v = x->data();
  const double* a = lower_.data();
  const size_t n = static_cast<size_t>(n_);
  for (size_t j = 0; j < n; ++j) {  // L y = b, by columns
    const double* column_j = a + j * n;
    v[j] /= column_j[j];
    const double vj = v[j];
    for (size_t i = j + 1; i < n; ++i) v[i] -= column_j[i] * vj;
  }
  for (size_t j = n; j-- > 0;) {  // L' x = y: row j of L' is column j of L
    const double* column_j = a + j * n;
    double sum = v[j];
    for (size_t i = j + 1; i < n; ++i) sum -= column_j[i] * v[i];
    v[j] = sum / column_j[j];
  }
}

}  // namespace dream::barriers
