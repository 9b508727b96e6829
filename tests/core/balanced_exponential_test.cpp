// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/base/balanced_exponential.hpp: the balancing
// is an exact diagonal similarity that evens out row and column norms, and
// the balanced exponential equals the exponential.
#include "ctid/base/balanced_exponential.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"

namespace ctid {
namespace {

// The companion matrix of (s + 10)(s + 100)(s + 1000) = s^3 + 1110 s^2 +
// 111000 s + 1e6 (badly scaled).
Eigen::MatrixXd companion() {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3);
  a(0, 1) = 1;
  a(1, 2) = 1;
  a.row(2) << -1e6, -1.11e5, -1110;
  return a;
}

TEST(BalanceDiagonal, IsAnExactSimilarityWithPowersOfTwo) {
  const Eigen::MatrixXd a = companion();
  Eigen::MatrixXd b = a;
  const Eigen::VectorXd d = balance_diagonal(b);
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    int exponent = 0;
    EXPECT_EQ(std::frexp(d(i), &exponent), 0.5) << "d(" << i << ") = " << d(i);
  }
  // D^-1 A D entry by entry, exactly (scaling by powers of 2 rounds nothing)
  for (Eigen::Index i = 0; i < 3; ++i) {
    for (Eigen::Index j = 0; j < 3; ++j) {
      EXPECT_EQ(b(i, j), a(i, j) * d(j) / d(i)) << i << "," << j;
    }
  }
  // off-diagonal row and column 1-norms within a factor radix^2 = 4 of
  // each other after balancing (before: 1e6 against 1)
  for (Eigen::Index i = 0; i < 3; ++i) {
    const double r = b.row(i).cwiseAbs().sum() - std::abs(b(i, i));
    const double c = b.col(i).cwiseAbs().sum() - std::abs(b(i, i));
    EXPECT_LT(std::max(r / c, c / r), 4.0) << "row/column " << i;
  }
}

TEST(BalanceDiagonal, LeavesZeroRowsAndColumnsAlone) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3);
  a(0, 1) = 1e6;
  a(1, 0) = -1;
  a(0, 2) = 5;  // column 2 only: its row is zero
  Eigen::MatrixXd b = a;
  const Eigen::VectorXd d = balance_diagonal(b);
  EXPECT_EQ(d(2), 1.0);
  EXPECT_TRUE(b.row(2).isZero());
}

// A well-scaled matrix: the balanced exponential is the exponential.
TEST(BalancedExp, EqualsTheExponentialOfAWellScaledMatrix) {
  Eigen::MatrixXd a(3, 3);
  a << -1, 0.5, 0, -0.3, -2, 1, 0.2, 0, -0.5;
  EXPECT_TRUE(test::MatrixNear(balanced_exp<double>(a),
                               Eigen::MatrixXd(a.exp()), 1e-14));
}

// exp(A h), h = 0.01, of the badly scaled companion matrix against its
// eigendecomposition, known in closed form: eigenvalues -10, -100, -1000,
// eigenvectors [1; l; l^2] (a Vandermonde matrix), exp(A h) = V exp(L h)
// V^-1.
TEST(BalancedExp, MatchesTheEigendecompositionOfABadlyScaledCompanion) {
  const double h = 0.01;
  const Eigen::MatrixXd a = companion() * h;
  const Eigen::Vector3d l(-10, -100, -1000);
  Eigen::Matrix3d v;
  for (int j = 0; j < 3; ++j) v.col(j) << 1, l(j), l(j) * l(j);
  const Eigen::Vector3d el = (l * h).array().exp();
  const Eigen::Matrix3d exact = v * el.asDiagonal() * v.inverse();
  const Eigen::MatrixXd balanced = balanced_exp<double>(a);
  // entry by entry relative to the row's largest entry of the exact result
  for (Eigen::Index i = 0; i < 3; ++i) {
    const double scale = exact.row(i).cwiseAbs().maxCoeff();
    for (Eigen::Index j = 0; j < 3; ++j) {
      EXPECT_NEAR(balanced(i, j), exact(i, j), 1e-10 * scale)
          << i << "," << j;
    }
  }
}

}  // namespace
}  // namespace ctid
