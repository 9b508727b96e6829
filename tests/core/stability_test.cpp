// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/base/stability.hpp: the Routh test against the
// roots computed by an eigenvalue solver, and the reflection of roots into
// the left half plane and into the unit disc (the roots of the result
// against the input's roots reflected by hand, found by Eigen's polynomial
// solver).
#include "ctid/base/stability.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <random>
#include <unsupported/Eigen/Polynomials>
#include <vector>

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

using Complex = std::complex<double>;

// [a1 .. an] of prod (z - r) over the roots, a complex pair given once
// (by its root with positive imaginary part), by convolution of the real
// factors z - r and z^2 - 2 Re(r) z + |r|^2.
Eigen::VectorXd monic_of(const std::vector<Complex>& roots) {
  std::vector<double> p{1.0};
  for (const Complex& r : roots) {
    const std::vector<double> factor =
        r.imag() == 0 ? std::vector<double>{1.0, -r.real()}
                      : std::vector<double>{1.0, -2 * r.real(), std::norm(r)};
    std::vector<double> q(p.size() + factor.size() - 1, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < factor.size(); ++j)
        q[i + j] += p[i] * factor[j];
    p = q;
  }
  return Eigen::Map<Eigen::VectorXd>(p.data() + 1, p.size() - 1);
}

// The roots of z^n + a1 z^(n-1) + .. + an by Eigen's polynomial solver.
std::vector<Complex> roots_of(const Eigen::VectorXd& a) {
  const Eigen::Index n = a.size();
  Eigen::VectorXd ascending(n + 1);
  ascending(n) = 1;
  for (Eigen::Index i = 0; i < n; ++i) ascending(n - 1 - i) = a(i);
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(ascending);
  const auto& r = solver.roots();
  return std::vector<Complex>(r.data(), r.data() + r.size());
}

// Every expected root (a pair by its upper root, as monic_of) is a root
// of a, and a has no other.
void expect_roots(const Eigen::VectorXd& a, const std::vector<Complex>& pairs) {
  std::vector<Complex> expected;
  for (const Complex& r : pairs) {
    expected.push_back(r);
    if (r.imag() != 0) expected.push_back(std::conj(r));
  }
  std::vector<Complex> found = roots_of(a);
  ASSERT_EQ(found.size(), expected.size());
  for (const Complex& r : expected) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < found.size(); ++k)
      if (std::abs(found[k] - r) < std::abs(found[best] - r)) best = k;
    EXPECT_NEAR(std::abs(found[best] - r), 0.0, 1e-9)
        << "root " << r.real() << " + " << r.imag() << "j";
    found.erase(found.begin() + static_cast<std::ptrdiff_t>(best));
  }
}

TEST(ReflectRootsIntoUnitDisc, ReflectsOutsideRootsAndPullsThoseNearTheCircle) {
  // Outside: 2 and 1.25 e^(+-0.7j), reflected to 1/conj(z); inside but at
  // |z| >= 0.999: -0.9995, moved to -0.99; the rest stays.
  const Complex outer = std::polar(1.25, 0.7);
  const Eigen::VectorXd a =
      monic_of({2.0, Complex(0.5, 0.6), -0.9995, outer, 0.3});
  bool moved = false;
  const Eigen::VectorXd r =
      reflect_roots_into_unit_disc<double>(a, 0.999, 0.99, &moved);
  EXPECT_TRUE(moved);
  expect_roots(r, {0.5, Complex(0.5, 0.6), -0.99, 1.0 / std::conj(outer), 0.3});
}

TEST(ReflectRootsIntoUnitDisc, WithTheLimitOneReflectsTheOutsideRootsOnly) {
  // Limit 1: 3, -1.0001 and 1.5 e^(+-1.1j) become 1/conj(z) (-1/1.0001
  // stays, inside the circle); 0.9995 inside stays.
  const Complex outer = std::polar(1.5, 1.1);
  const Eigen::VectorXd a = monic_of({-1.0001, outer, 0.9995, 3.0});
  bool moved = false;
  const Eigen::VectorXd r =
      reflect_roots_into_unit_disc<double>(a, 1.0, 0.999, &moved);
  EXPECT_TRUE(moved);
  expect_roots(r, {-1 / 1.0001, 1.0 / std::conj(outer), 0.9995, 1.0 / 3});
}

TEST(ReflectRootsIntoUnitDisc, KeepsAPolynomialWithItsRootsInside) {
  const Eigen::VectorXd a = monic_of({Complex(0.2, 0.7), -0.5, 0.95});
  bool moved = true;
  const Eigen::VectorXd r =
      reflect_roots_into_unit_disc<double>(a, 0.999, 0.99, &moved);
  EXPECT_FALSE(moved);
  EXPECT_TRUE(test::MatrixNear(r, a, 1e-12));
  EXPECT_EQ(reflect_roots_into_unit_disc<double>(Eigen::VectorXd(), 1.0, 0.999)
                .size(),
            0);
}

}  // namespace
}  // namespace ctid
