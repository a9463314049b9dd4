#pragma once

#include <Eigen/Core>

namespace dream::barriers {

/// How an InteriorPointQp solve ended.
enum class QpStatus {
  kOptimal,         ///< the stopping tests passed (CVXOPT's 'optimal')
  kIterationLimit,  ///< max_iterations reached (CVXOPT's 'unknown')
  kSingularSystem,  ///< a KKT factorization failed (CVXOPT raises or says 'unknown')
  kNotFinite,       ///< NaN or infinity in the data or an iterate, or a zero gap CVXOPT divides by
};

struct QpSolution {
  QpStatus status = QpStatus::kNotFinite;
  Eigen::VectorXd x;
  int iterations = 0;
};

}  // namespace dream::barriers
