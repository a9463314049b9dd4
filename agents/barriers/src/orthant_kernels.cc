#include "orthant_kernels.h"

#include <cmath>

namespace dream::barriers::orthant {

DREAM_VECTOR_CLONES void Direction(size_t m, double target, const double* __restrict lambda,
                                   const double* __restrict inverse_lambda, const double* __restrict correction,
                                   const double* __restrict d, const double* __restrict rz, double* __restrict ds,
                                   double* __restrict dz) {
  if (correction == nullptr) {
    for (size_t i = 0; i < m; ++i) ds[i] = (-(lambda[i] * lambda[i]) + target) * inverse_lambda[i];
  } else {
    for (size_t i = 0; i < m; ++i) ds[i] = ((-(lambda[i] * lambda[i]) - correction[i]) + target) * inverse_lambda[i];
  }
  for (size_t i = 0; i < m; ++i) dz[i] = -rz[i] - d[i] * ds[i];
}

DREAM_VECTOR_CLONES void ScaleTwice(size_t m, const double* __restrict di, double* __restrict z,
                                    double* __restrict scaled) {
  for (size_t i = 0; i < m; ++i) {
    z[i] *= di[i];
    scaled[i] = z[i] * di[i];
  }
}

DREAM_VECTOR_CLONES void ScaledDifference(size_t m, const double* __restrict gx, const double* __restrict di,
                                          double* __restrict z) {
  for (size_t i = 0; i < m; ++i) z[i] = gx[i] * di[i] - z[i];
}

DREAM_VECTOR_CLONES void Subtract(size_t m, const double* __restrict dz, double* __restrict ds) {
  for (size_t i = 0; i < m; ++i) ds[i] -= dz[i];
}

DREAM_VECTOR_CLONES void Rescale(size_t m, const double* __restrict inverse_lambda, double* __restrict ds,
                                 double* __restrict dz, double* __restrict correction) {
  if (correction != nullptr) {
    for (size_t i = 0; i < m; ++i) correction[i] = ds[i] * dz[i];
  }
  for (size_t i = 0; i < m; ++i) {
    ds[i] *= inverse_lambda[i];
    dz[i] *= inverse_lambda[i];
  }
}

DREAM_VECTOR_CLONES void UpdateScaling(size_t m, double step, const double* __restrict ds, const double* __restrict dz,
                                       double* __restrict lambda, double* __restrict inverse_lambda,
                                       double* __restrict d, double* __restrict di, double* __restrict s,
                                       double* __restrict z) {
  for (size_t i = 0; i < m; ++i) {
    const double u = (1.0 + step * ds[i]) * lambda[i];
    const double v = (1.0 + step * dz[i]) * lambda[i];
    const double l = std::sqrt(u * v);
    const double scale = d[i] * (l / v);
    lambda[i] = l;
    inverse_lambda[i] = 1.0 / l;
    d[i] = scale;
    di[i] = 1.0 / scale;
    s[i] = scale * l;
    z[i] = di[i] * l;
  }
}

DREAM_VECTOR_CLONES void PrimalResidual(size_t m, const double* __restrict s, const double* __restrict h,
                                        const double* __restrict gx, double* __restrict rz) {
  for (size_t i = 0; i < m; ++i) rz[i] = s[i] - h[i] + gx[i];
}

}  // namespace dream::barriers::orthant
