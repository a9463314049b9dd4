#pragma once

// The interior-point QP's element-by-element work over the m constraint rows
// (InteriorPointQp::Step, SolveKkt, ComputeResiduals), as plain loops over
// raw arrays. At 20 robots m = 430, and these loops were a third of a step
// as Eigen expressions: Eigen picks its vector width when it is compiled (2
// doubles on x86-64's baseline), while these loops are built for AVX2 too
// (vector_clones.h). No two arrays given to one call overlap (__restrict),
// which lets the compiler vectorize them.
#include <cstddef>

#include "vector_clones.h"

namespace dream::barriers::orthant {

/// The predictor's (correction null) or the corrector's right-hand side:
/// ds = (target - lambda^2 [- correction]) / lambda, dz = -rz - d ds.
void Direction(size_t m, double target, const double* __restrict lambda, const double* __restrict inverse_lambda,
               const double* __restrict correction, const double* __restrict d, const double* __restrict rz,
               double* __restrict ds, double* __restrict dz);

/// z := z / d (W^-T bz) and scaled := z / d (W^-1 W^-T bz), di = 1 / d.
void ScaleTwice(size_t m, const double* __restrict di, double* __restrict z, double* __restrict scaled);

/// z := gx / d - z: W uz from G ux and W^-T bz.
void ScaledDifference(size_t m, const double* __restrict gx, const double* __restrict di, double* __restrict z);

/// ds := ds - dz.
void Subtract(size_t m, const double* __restrict dz, double* __restrict ds);

/// correction := ds dz (when non-null), then ds and dz divided by lambda.
void Rescale(size_t m, const double* __restrict inverse_lambda, double* __restrict ds, double* __restrict dz,
             double* __restrict correction);

/// The scaling's update after a step of `step` along (ds, dz): u = (1 + step ds) lambda,
/// v = (1 + step dz) lambda; lambda := sqrt(u v), d := d lambda / v, di := 1 / d,
/// s := d lambda, z := di lambda, inverse_lambda := 1 / lambda.
void UpdateScaling(size_t m, double step, const double* __restrict ds, const double* __restrict dz,
                   double* __restrict lambda, double* __restrict inverse_lambda, double* __restrict d,
                   double* __restrict di, double* __restrict s, double* __restrict z);

/// rz := s - h + gx.
void PrimalResidual(size_t m, const double* __restrict s, const double* __restrict h, const double* __restrict gx,
                    double* __restrict rz);

}  // namespace dream::barriers::orthant
