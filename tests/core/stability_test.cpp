// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/base/stability.hpp: the Routh test against the
// roots computed by an eigenvalue solver, and the reflection of roots.
#include "ctid/base/stability.hpp"

#include <gtest/gtest.h>

#include <random>

#include "test_util.hpp"

namespace ctid {
namespace {

bool stable_by_roots(const Eigen::VectorXd& a) {
  const Eigen::Index n = a.size();
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) c(i + 1, i) = 1;
  for (Eigen::Index i = 0; i < n; ++i) c(0, i) = -a(i);
  return Eigen::EigenSolver<Eigen::MatrixXd>(c, false)
             .eigenvalues()
             .real()
             .maxCoeff() < 0;
}

TEST(HurwitzTest, AgreesWithTheRootsOnRandomPolynomials) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> coef(-1.0, 5.0);
  int stable = 0;
  for (int n = 1; n <= 6; ++n) {
    HurwitzTest<double> test(n);
    for (int trial = 0; trial < 500; ++trial) {
      Eigen::VectorXd a(n);
      for (int i = 0; i < n; ++i) a(i) = coef(rng);
      const bool expected = stable_by_roots(a);
      stable += expected;
      ASSERT_EQ(test.is_stable(a), expected)
          << "n " << n << " a " << a.transpose();
    }
  }
  EXPECT_GT(stable, 100) << "the sample must contain stable polynomials";
}

TEST(HurwitzTest, RejectsMarginalAndNonFinite) {
  HurwitzTest<double> test(2);
  EXPECT_FALSE(test.is_stable(Eigen::Vector2d(0, 4)));  // roots +-2j
  EXPECT_FALSE(test.is_stable(Eigen::Vector2d(2, 0)));  // root at 0
  EXPECT_FALSE(test.is_stable(Eigen::Vector2d(NAN, 1)));
  EXPECT_TRUE(test.is_stable(Eigen::Vector2d(2.4, 4)));
}

TEST(ReflectUnstableRoots, MirrorsIntoTheLeftHalfPlane) {
  // (p - 1)(p + 2) = p^2 + p - 2  ->  (p + 1)(p + 2) = p^2 + 3p + 2.
  const Eigen::VectorXd r =
      reflect_unstable_roots<double>(Eigen::Vector2d(1, -2));
  EXPECT_TRUE(test::MatrixNear(r, Eigen::Vector2d(3, 2), 1e-12));
  // Complex pair 1 +- 2j: p^2 - 2p + 5 -> p^2 + 2p + 5.
  const Eigen::VectorXd c =
      reflect_unstable_roots<double>(Eigen::Vector2d(-2, 5));
  EXPECT_TRUE(test::MatrixNear(c, Eigen::Vector2d(2, 5), 1e-12));
  HurwitzTest<double> test(2);
  EXPECT_TRUE(
      test.is_stable(reflect_unstable_roots<double>(Eigen::Vector2d(0, 4))));
}

}  // namespace
}  // namespace ctid
