// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/base/polynomial_inverse.hpp (and the helpers of
// base/polynomial.hpp it uses): g(x_k) = v_k, the branch followed from
// sample to sample, the closed-form root of a quadratic, and the failures.
#include "ctid/base/polynomial_inverse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ctid {
namespace {

double g(const Eigen::VectorXd& beta, double x) {
  double value = 0, power = 1;
  for (Eigen::Index i = 0; i < beta.size(); ++i) {
    power *= x;
    value += beta(i) * power;
  }
  return value;
}

TEST(PolynomialHelpers, ProductValueDerivativeAndRoots) {
  // (1 + 2x)(3 - x + x^2) = 3 + 5x - x^2 + 2x^3
  const Eigen::VectorXd p =
      convolve<double>(Eigen::Vector2d(1, 2), Eigen::Vector3d(3, -1, 1));
  EXPECT_EQ(p, Eigen::Vector4d(3, 5, -1, 2));
  EXPECT_DOUBLE_EQ(polynomial_value<double>(p, 2.0), 3 + 10 - 4 + 16);
  EXPECT_EQ(polynomial_derivative<double>(p), Eigen::Vector3d(5, -2, 6));
  // (x - 1)(x + 2)(x - 3) = x^3 - 2x^2 - 5x + 6
  const auto r = polynomial_roots<double>(Eigen::Vector4d(6, -5, -2, 1));
  std::vector<double> re;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    EXPECT_NEAR(r(i).imag(), 0, 1e-14);
    re.push_back(r(i).real());
  }
  std::sort(re.begin(), re.end());
  EXPECT_NEAR(re[0], -2, 1e-14);
  EXPECT_NEAR(re[1], 1, 1e-14);
  EXPECT_NEAR(re[2], 3, 1e-14);
  Eigen::VectorXcd roots(3);
  roots << 1, std::complex<double>(0, 2), std::complex<double>(0, -2);
  const Eigen::VectorXcd c =
      monic_from_roots<double>(roots);  // x^3 - x^2 + 4x - 4
  EXPECT_NEAR(std::abs(c(0) - 1.0), 0, 1e-15);
  EXPECT_NEAR(std::abs(c(1) + 1.0), 0, 1e-15);
  EXPECT_NEAR(std::abs(c(2) - 4.0), 0, 1e-15);
  EXPECT_NEAR(std::abs(c(3) + 4.0), 0, 1e-15);
}

// Monotonic: the unique root, g(x) = v to a few eps of the terms' size.
TEST(InvertPolynomial, MonotonicCubicAndQuintic) {
  for (const Eigen::VectorXd& beta :
       {Eigen::VectorXd(Eigen::Vector3d(2, 0, 0.5)),
        Eigen::VectorXd(
            (Eigen::VectorXd(5) << 1, 0.3, 0.2, 0, 0.01).finished())}) {
    std::vector<double> v;
    for (double s : {-1e6, -30.0, -1.0, -1e-9, 0.0, 1e-12, 0.7, 5.0, 1e4}) {
      v.push_back(s);
    }
    std::vector<double> x(v.size());
    ASSERT_TRUE(
        invert_polynomial<double>(beta, v.data(), v.size(), x.data()).ok());
    for (std::size_t k = 0; k < v.size(); ++k) {
      // rounding of g at x: eps times the sum of |terms|
      double terms = 0, power = 1;
      for (Eigen::Index i = 0; i < beta.size(); ++i) {
        power *= std::abs(x[k]);
        terms += std::abs(beta(i)) * power;
      }
      EXPECT_NEAR(g(beta, x[k]), v[k], 8 * 2.2e-16 * std::max(terms, 1e-300))
          << "v = " << v[k];
    }
  }
}

// g' = (1 + x)^2 >= 0: monotonic although g' has a (double) real root.
TEST(InvertPolynomial, MonotonicWithStationaryPoint) {
  const Eigen::Vector3d beta(1, 1, 1.0 / 3);
  std::vector<double> truth = {-4, -2, -0.5, 0, 0.3, 2, 5};
  std::vector<double> v, x(truth.size());
  for (double t : truth) v.push_back(g(beta, t));
  ASSERT_TRUE(
      invert_polynomial<double>(beta, v.data(), v.size(), x.data()).ok());
  for (std::size_t k = 0; k < truth.size(); ++k) {
    EXPECT_NEAR(x[k], truth[k], 1e-12 * (1 + std::abs(truth[k])));
  }
}

// Not monotonic: x + x^2 = v, x = (-1 + sqrt(1 + 4v)) / 2 on the branch
// the first sample selects (the root nearest to v_0), followed after.
TEST(InvertPolynomial, QuadraticFollowsTheBranch) {
  const Eigen::Vector2d beta(1, 1);
  std::vector<double> v, x(40);
  for (int k = 0; k < 40; ++k) v.push_back(0.75 + 0.2 * k);
  ASSERT_TRUE(invert_polynomial<double>(beta, v.data(), 40, x.data()).ok());
  for (int k = 0; k < 40; ++k) {
    const double exact = (-1 + std::sqrt(1 + 4 * v[k])) / 2;
    EXPECT_NEAR(x[k], exact, 1e-14 * (1 + exact)) << "sample " << k;
  }
}

// x - x^3 has three real branches on |v| < 2/(3 sqrt 3); started on the
// middle one, the inverse stays on it.
TEST(InvertPolynomial, CubicStaysOnTheMiddleBranch) {
  const Eigen::Vector3d beta(1, 0, -1);
  std::vector<double> truth, v;
  for (int k = 0; k < 50; ++k) truth.push_back(0.5 * std::sin(0.2 * k));
  for (double t : truth) v.push_back(g(beta, t));
  std::vector<double> x(v.size());
  ASSERT_TRUE(
      invert_polynomial<double>(beta, v.data(), v.size(), x.data()).ok());
  for (std::size_t k = 0; k < v.size(); ++k) {
    EXPECT_NEAR(x[k], truth[k], 1e-13) << "sample " << k;
  }
}

TEST(InvertPolynomial, LinearInPlaceAndFailures) {
  std::vector<double> v = {1, -2, 4};
  ASSERT_TRUE(
      invert_polynomial<double>(Eigen::Vector3d(2, 0, 0), v.data(), 3, v.data())
          .ok());
  EXPECT_EQ(v, (std::vector<double>{0.5, -1, 2}));
  std::vector<double> x(3);
  EXPECT_EQ(
      invert_polynomial<double>(Eigen::Vector2d(0, 0), v.data(), 3, x.data())
          .code(),
      ErrorCode::kBadInput);
  // x + x^2 >= -1/4: no real root for v = -1
  std::vector<double> low = {1, 0, -1};
  EXPECT_EQ(
      invert_polynomial<double>(Eigen::Vector2d(1, 1), low.data(), 3, x.data())
          .code(),
      ErrorCode::kNumericalFailure);
  low[1] = NAN;
  EXPECT_EQ(
      invert_polynomial<double>(Eigen::Vector2d(1, 1), low.data(), 3, x.data())
          .code(),
      ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
