// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/prefilter.hpp
// (prefilter_denominator), each against polynomials written from their
// roots by hand:
//   - a stable F with well separated, damped roots comes back unchanged
//     (monic);
//   - an integrator moves to -wlo, an unstable root is reflected, an
//     undamped pair gets the damping 1e-3 |r|, a double root is split by
//     the factor 1.02;
//   - on polynomials with double, clustered, unstable and undamped roots
//     (moduli within a decade of 1) the result is stable, damped by at
//     least 1e-3 and its roots at least 1e-2 of their modulus apart (with
//     a margin of 10 % for the rounding of the roots found from the
//     result's coefficients);
//   - bad input is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/prefilter.hpp"

namespace ctid::residtrace {
namespace {

using C = std::complex<double>;

// Monic polynomial (descending powers) from its roots.
Eigen::VectorXd poly(const std::vector<C>& r) {
  return real_monic_from_roots<double>(r);
}

std::vector<C> roots(const Eigen::VectorXd& F) {
  const Eigen::Index n = F.size() - 1;
  Eigen::VectorXd a(n + 1);
  for (Eigen::Index i = 0; i <= n; ++i) a(i) = F(n - i);
  const auto z = polynomial_roots<double>(a);
  return std::vector<C>(z.data(), z.data() + z.size());
}

Eigen::VectorXd prefilter(const Eigen::VectorXd& F, double wlo) {
  Eigen::VectorXd Fp;
  const Status s = prefilter_denominator<double>(F, wlo, &Fp);
  EXPECT_TRUE(s.ok()) << s.message();
  return Fp;
}

void expect_near(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                 double tol) {
  ASSERT_EQ(a.size(), b.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a(i), b(i), tol * std::max(1.0, std::abs(b(i)))) << i;
  }
}

TEST(ResidtracePrefilter, WellSeparatedStableDenominatorUnchanged) {
  const Eigen::VectorXd F = poly({C(-1, 0), C(-3, 0), C(-1, 2), C(-1, -2)});
  expect_near(prefilter(2.5 * F, 0.1), F, 1e-12);
}

TEST(ResidtracePrefilter, IntegratorUnstableAndUndampedRootsMoved) {
  // p (p + 2), wlo 0.5: the integrator to -0.5
  expect_near(prefilter(poly({C(0, 0), C(-2, 0)}), 0.5),
              poly({C(-0.5, 0), C(-2, 0)}), 1e-12);
  // (p - 2)(p + 5): the unstable root reflected
  expect_near(prefilter(poly({C(2, 0), C(-5, 0)}), 0.1),
              poly({C(-2, 0), C(-5, 0)}), 1e-12);
  // p^2 + 4: the pair gets the real part -1e-3 * 2
  expect_near(prefilter(poly({C(0, 2), C(0, -2)}), 0.1),
              poly({C(-2e-3, 2), C(-2e-3, -2)}), 1e-9);
  // (p + 1)^2: split into (p + 1)(p + 1.02)
  expect_near(prefilter(poly({C(-1, 0), C(-1, 0)}), 0.1),
              poly({C(-1, 0), C(-1.02, 0)}), 1e-6);
}

TEST(ResidtracePrefilter, ResultStableDampedAndSeparated) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // clusters of roots around a few centres, some repeated exactly, some
    // unstable or undamped
    std::vector<C> r;
    const int clusters = 1 + trial % 3;
    for (int k = 0; k < clusters; ++k) {
      const double m = std::pow(10.0, U(rng));
      const bool complex_pair = U(rng) > 0;
      const int copies = 1 + (trial + k) % 2;
      for (int j = 0; j < copies; ++j) {
        const double jitter = (trial % 2 == 0) ? 0.0 : 1e-3 * m * U(rng);
        if (complex_pair) {
          // undamped pairs in every fifth trial
          const double re = m * (trial % 5 == 0 ? 0.0 : U(rng)) + jitter;
          r.emplace_back(re, m);
          r.emplace_back(re, -m);
        } else {
          r.emplace_back(m * U(rng) + jitter, 0);
        }
      }
    }
    if (trial % 5 == 0) r.emplace_back(0, 0);  // an integrator
    const Eigen::VectorXd Fp = prefilter(poly(r), 0.05);
    ASSERT_EQ(Fp.size(), static_cast<Eigen::Index>(r.size()) + 1);
    EXPECT_EQ(Fp(0), 1.0);
    const std::vector<C> z = roots(Fp);
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double m = std::abs(z[i]);
      EXPECT_LT(z[i].real(), -0.9e-3 * m) << "trial " << trial;
      for (std::size_t j = i + 1; j < z.size(); ++j) {
        const double mm = std::max(m, std::abs(z[j]));
        EXPECT_GT(std::abs(z[i] - z[j]), 0.9e-2 * mm) << "trial " << trial;
      }
    }
  }
}

TEST(ResidtracePrefilter, BadInputRefused) {
  Eigen::VectorXd Fp;
  Eigen::VectorXd F(3);
  F << 1, 2, 1;
  EXPECT_FALSE(prefilter_denominator<double>(F, 0.0, &Fp).ok());
  EXPECT_FALSE(prefilter_denominator<double>(F, NAN, &Fp).ok());
  EXPECT_FALSE(prefilter_denominator<double>(F, 1.0, nullptr).ok());
  F(0) = 0;
  EXPECT_FALSE(prefilter_denominator<double>(F, 1.0, &Fp).ok());
  F << 1, NAN, 1;
  EXPECT_FALSE(prefilter_denominator<double>(F, 1.0, &Fp).ok());
  EXPECT_FALSE(prefilter_denominator<double>(Eigen::VectorXd(), 1.0, &Fp).ok());
}

}  // namespace
}  // namespace ctid::residtrace
