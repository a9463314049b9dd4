// DenseCholesky, the barrier QP's factorization: four columns at a time, then
// one at a time for what is left, so every size n mod 4 takes its own path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "dream/barriers/dense_cholesky.h"

namespace dream::barriers {
namespace {

/// A random symmetric positive definite matrix of size n (fixed seed per n).
Eigen::MatrixXd RandomSpd(int n) {
  std::srand(static_cast<unsigned>(1000 + n));
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  return a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

void Load(const Eigen::MatrixXd& s, DenseCholesky* cholesky) {
  const int n = static_cast<int>(s.rows());
  cholesky->Reset(n);
  for (int column = 0; column < n; ++column) {
    for (int row = column; row < n; ++row) cholesky->AddLower(row, column, s(row, column));
  }
}

TEST(DenseCholeskyTest, SolvesAsEigensLltForEverySizeUpToThirteen) {
  DenseCholesky cholesky;
  for (int n = 1; n <= 13; ++n) {
    const Eigen::MatrixXd s = RandomSpd(n);
    Load(s, &cholesky);
    ASSERT_TRUE(cholesky.Factor()) << "n = " << n;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    Eigen::VectorXd x = b;
    cholesky.SolveInPlace(&x);
    const Eigen::VectorXd expected = s.llt().solve(b);
    EXPECT_LE((x - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff()) << "n = " << n;
    EXPECT_LE((s * x - b).cwiseAbs().maxCoeff(), 1e-11) << "n = " << n;
  }
}

TEST(DenseCholeskyTest, AddedDiagonalAndReuseAfterResetFactorTheNewMatrix) {
  DenseCholesky cholesky;
  const Eigen::MatrixXd big = RandomSpd(9);
  Load(big, &cholesky);
  ASSERT_TRUE(cholesky.Factor());
  // The same solver again, smaller, with the diagonal added separately (as the QP adds P).
  const Eigen::MatrixXd s = RandomSpd(6);
  const Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(6, 2.5);
  Load(s, &cholesky);
  cholesky.AddDiagonal(diagonal);
  ASSERT_TRUE(cholesky.Factor());
  Eigen::VectorXd x = Eigen::VectorXd::Ones(6);
  cholesky.SolveInPlace(&x);
  const Eigen::MatrixXd full = s + Eigen::MatrixXd(diagonal.asDiagonal());
  EXPECT_LE((full * x - Eigen::VectorXd::Ones(6)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DenseCholeskyTest, NotPositiveDefiniteIsRefusedInEveryColumnOfAPanel) {
  DenseCholesky cholesky;
  for (int bad = 0; bad < 6; ++bad) {  // columns 0-3 are the first panel, 4-5 the rest
    Eigen::MatrixXd s = Eigen::MatrixXd::Identity(6, 6);
    s(bad, bad) = bad % 2 == 0 ? -1.0 : 0.0;
    Load(s, &cholesky);
    EXPECT_FALSE(cholesky.Factor()) << "pivot " << bad;
  }
  Eigen::MatrixXd nan = Eigen::MatrixXd::Identity(5, 5);
  nan(2, 2) = std::nan("");
  Load(nan, &cholesky);
  EXPECT_FALSE(cholesky.Factor());
}

}  // namespace
}  // namespace dream::barriers
