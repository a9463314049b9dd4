#include "dream/barriers/dense_cholesky.h"

#include <cmath>

#include "vector_clones.h"

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

DREAM_VECTOR_CLONES bool DenseCholesky::FactorFourColumns(size_t j) {
  double* a = lower_.data();
  const size_t n = static_cast<size_t>(n_);
  double* c0 = a + j * n;
  double* c1 = c0 + n;
  double* c2 = c1 + n;
  double* c3 = c2 + n;
  // The panel itself, column by column (each updated by the ones before it).
  if (!FactorColumn(j)) return false;
  for (size_t i = j + 1; i < n; ++i) c1[i] -= c0[j + 1] * c0[i];
  if (!FactorColumn(j + 1)) return false;
  for (size_t i = j + 2; i < n; ++i) c2[i] -= c0[j + 2] * c0[i] + c1[j + 2] * c1[i];
  if (!FactorColumn(j + 2)) return false;
  for (size_t i = j + 3; i < n; ++i) c3[i] -= c0[j + 3] * c0[i] + c1[j + 3] * c1[i] + c2[j + 3] * c2[i];
  if (!FactorColumn(j + 3)) return false;
  // The trailing triangle, rank 4: each of its columns read and written once per four.
  for (size_t k = j + 4; k < n; ++k) {
    double* column_k = a + k * n;
    const double f0 = c0[k], f1 = c1[k], f2 = c2[k], f3 = c3[k];
    for (size_t i = k; i < n; ++i) column_k[i] -= f0 * c0[i] + f1 * c1[i] + f2 * c2[i] + f3 * c3[i];
  }
  return true;
}

DREAM_VECTOR_CLONES bool DenseCholesky::Factor() {
  double* a = lower_.data();
  const size_t n = static_cast<size_t>(n_);
  size_t j = 0;
  for (; j + 3 < n; j += 4) {
    if (!FactorFourColumns(j)) return false;
  }
  // What is left (n not a multiple of four): one column at a time.
  for (; j < n; ++j) {
    if (!FactorColumn(j)) return false;
    const double* column_j = a + j * n;
    for (size_t k = j + 1; k < n; ++k) {
      double* column_k = a + k * n;
      const double f = column_j[k];
      for (size_t i = k; i < n; ++i) column_k[i] -= f * column_j[i];
    }
  }
  // L' by columns too, so the backward solve runs over contiguous memory.
  upper_.resize(n * n);  // only its upper triangle is written and read
  for (size_t c = 0; c < n; ++c) {
    for (size_t r = c; r < n; ++r) upper_[r * n + c] = a[c * n + r];
  }
  return true;
}

DREAM_VECTOR_CLONES void DenseCholesky::SolveInPlace(Eigen::VectorXd* x) const {
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
