// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/filters/focus_filter.hpp: the prewarped Tustin
// Butterworth has the closed-form magnitude
//   |L(e^(i w Ts))|^2 = 1 / (1 + (tan(w Ts/2) / tan(wc Ts/2))^(2n))
// (low-pass; the ratio inverted for the high-pass), and the filtered
// signal satisfies the difference equation of the coefficients.
#include "ctid/filters/focus_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "test_util.hpp"

namespace ctid {
namespace {

const double kPi = 3.14159265358979323846;

// |L(q)|^2 at q = e^(-i w Ts), and its sensitivity to a relative rounding
// of every coefficient: sum |b_i| / |B(q)| + sum |a_i| / |A(q)| (the
// condition number of evaluating the two polynomials; the high-pass's poles
// cluster near z = 1, where the coefficient form loses digits).
double magnitude2(const DiscreteTransferFunction<double>& f, double w,
                  double ts, double* condition = nullptr) {
  const std::complex<double> q = std::exp(std::complex<double>(0, -w * ts));
  std::complex<double> num = 0, den = 0, power = 1;
  for (Eigen::Index i = 0;
       i < std::max(f.numerator.size(), f.denominator.size()); ++i) {
    if (i < f.numerator.size()) num += f.numerator(i) * power;
    if (i < f.denominator.size()) den += f.denominator(i) * power;
    power *= q;
  }
  if (condition != nullptr) {
    *condition = f.numerator.cwiseAbs().sum() / std::abs(num) +
                 f.denominator.cwiseAbs().sum() / std::abs(den);
  }
  return std::norm(num / den);
}

// 64 eps per unit of condition: the coefficients come from products of up
// to 8 root factors, each rounding once, and |L|^2 doubles the error.
double tolerance(double condition, double exact) {
  return 64 * 2.2e-16 * condition * (1 + exact);
}

double butterworth2(double w, double wc, double ts, int n, bool high) {
  double r = std::tan(w * ts / 2) / std::tan(wc * ts / 2);
  if (high) r = 1 / r;
  return 1 / (1 + std::pow(r, 2 * n));
}

TEST(FocusFilter, LowAndHighPassHaveTheButterworthMagnitude) {
  const double ts = 0.01;
  for (int n : {1, 2, 4, 5}) {
    for (bool high : {false, true}) {
      const double wc = high ? 3.0 : 40.0;
      const DiscreteTransferFunction<double> f =
          butterworth_tustin<double>(n, wc, ts, high);
      ASSERT_EQ(f.denominator.size(), n + 1);
      EXPECT_NEAR(f.denominator(0), 1, 1e-15);
      for (double w : {0.1, 1.0, 3.0, 10.0, 40.0, 100.0, 250.0}) {
        const double exact = butterworth2(w, wc, ts, n, high);
        double condition = 0;
        const double value = magnitude2(f, w, ts, &condition);
        EXPECT_NEAR(value, exact, tolerance(condition, exact))
            << "n " << n << (high ? " high" : " low") << " w " << w;
      }
    }
  }
}

TEST(FocusFilter, BandIsTheProductAndOmitsUselessHalves) {
  const double ts = 0.02;
  DiscreteTransferFunction<double> f;
  ASSERT_TRUE(focus_band_filter<double>(4, 2.0, 30.0, ts, f).ok());
  EXPECT_EQ(f.denominator.size(), 9);
  for (double w : {0.5, 2.0, 10.0, 30.0, 100.0}) {
    const double exact =
        butterworth2(w, 2.0, ts, 4, true) * butterworth2(w, 30.0, ts, 4, false);
    double condition = 0;
    const double value = magnitude2(f, w, ts, &condition);
    EXPECT_NEAR(value, exact, tolerance(condition, exact)) << w;
  }
  // w2 at or above Nyquist: the high-pass alone
  ASSERT_TRUE(focus_band_filter<double>(3, 2.0, kPi / ts, ts, f).ok());
  EXPECT_EQ(f.denominator.size(), 4);
  // [0, Inf): no filter at all
  ASSERT_TRUE(focus_band_filter<double>(3, 0.0, INFINITY, ts, f).ok());
  EXPECT_EQ(f.numerator, Eigen::VectorXd::Ones(1));
  EXPECT_EQ(f.denominator, Eigen::VectorXd::Ones(1));
}

TEST(FocusFilter, FilteredSignalSatisfiesTheDifferenceEquation) {
  DiscreteTransferFunction<double> f;
  ASSERT_TRUE(focus_band_filter<double>(2, 1.0, 20.0, 0.05, f).ok());
  const std::vector<double> u = test::binary_input(200, 4, 3);
  Eigen::MatrixXd x(200, 2);
  for (int k = 0; k < 200; ++k) {
    x(k, 0) = u[k];
    x(k, 1) = std::sin(0.1 * k);
  }
  Eigen::MatrixXd y = x;
  apply_filter(f, y);
  for (int j = 0; j < 2; ++j) {
    for (int k = 0; k < 200; ++k) {
      double lhs = 0, rhs = 0;  // sum a_i y_(k-i) = sum b_i x_(k-i)
      for (Eigen::Index i = 0; i < f.denominator.size() && i <= k; ++i) {
        lhs += f.denominator(i) * y(k - i, j);
      }
      for (Eigen::Index i = 0; i < f.numerator.size() && i <= k; ++i) {
        rhs += f.numerator(i) * x(k - i, j);
      }
      EXPECT_NEAR(lhs, rhs, 1e-13) << "column " << j << " sample " << k;
    }
  }
}

TEST(FocusFilter, RejectsBadBands) {
  DiscreteTransferFunction<double> f;
  EXPECT_EQ(focus_band_filter<double>(0, 1.0, 2.0, 0.1, f).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(focus_band_filter<double>(2, 3.0, 2.0, 0.1, f).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(focus_band_filter<double>(2, -1.0, 2.0, 0.1, f).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(focus_band_filter<double>(2, 1.0, 2.0, 0.0, f).code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
