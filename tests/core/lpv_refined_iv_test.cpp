// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/lpv_refined_iv.hpp: exact recovery of
// an LPV model from its noise-free output, consistency under white and
// coloured noise, fast sampling, and the errors.
#include "ctid/offline/lpv_refined_iv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "lpv_example.hpp"

namespace ctid {
namespace {

using test::Example;

struct Record {
  std::vector<double> u, p, chi;
};

Record example_record(int n, double ts, unsigned seed) {
  Record r;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1, 1);
  r.u.resize(n);
  r.p.resize(n);
  r.chi.resize(n);
  for (int k = 0; k < n; ++k) {
    r.u[k] = uni(rng);
    r.p[k] = std::sin(2 * M_PI * k * ts / 3);
  }
  return r;
}

TEST(LpvRefinedIvTest, RecoversTheModelFromNoiseFreeData) {
  const double ts = 0.005;
  const int n = 3001;
  Record r = example_record(n, ts, 1);
  Example ex(r.p);
  ASSERT_TRUE(simulate_lpv<double>(r.u.data(), n, ts, ex.a, ex.basis_a, ex.b,
                                   ex.basis_b, r.chi.data())
                  .ok());
  LpvProblem<double> problem{r.chi.data(), r.u.data(), n, ts,
                             ex.basis_a,   ex.basis_b, 0, 0};
  LpvResult<double> result;
  ASSERT_TRUE(
      lpv_refined_iv<double>(problem, LpvSettings<double>(), &result).ok());
  EXPECT_TRUE(result.converged);
  // The zero basis function of a2 is not a parameter.
  ASSERT_EQ(result.theta.size(), 9);
  EXPECT_LT((result.a - ex.a).norm(), 1e-7 * ex.a.norm());
  EXPECT_LT((result.b - ex.b).norm(), 1e-7 * ex.b.norm());
  EXPECT_LT(result.cost, 1e-14);
}

TEST(LpvRefinedIvTest, OutputErrorEstimateIsCloseUnderWhiteNoise) {
  const double ts = 0.005;
  const int n = 6001;
  Record r = example_record(n, ts, 2);
  Example ex(r.p);
  ASSERT_TRUE(simulate_lpv<double>(r.u.data(), n, ts, ex.a, ex.basis_a, ex.b,
                                   ex.basis_b, r.chi.data())
                  .ok());
  double power = 0;
  for (double v : r.chi) power += v * v / n;
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0, std::sqrt(power) * 0.1);  // 20 dB
  std::vector<double> y(n);
  for (int k = 0; k < n; ++k) y[k] = r.chi[k] + g(rng);
  LpvProblem<double> problem{y.data(),   r.u.data(), n, ts,
                             ex.basis_a, ex.basis_b, 0, 0};
  LpvResult<double> result;
  ASSERT_TRUE(
      lpv_refined_iv<double>(problem, LpvSettings<double>(), &result).ok());
  EXPECT_LT((result.a - ex.a).norm(), 0.1 * ex.a.norm());
  EXPECT_LT((result.b - ex.b).norm(), 0.1 * ex.b.norm());
  // The residual variance is the noise variance.
  EXPECT_NEAR(result.cost, power * 0.01, 0.15 * power * 0.01);
}

TEST(LpvRefinedIvTest, BoxJenkinsEstimatesTheNoiseModel) {
  const double ts = 0.005;
  const int n = 6001;
  Record r = example_record(n, ts, 4);
  Example ex(r.p);
  ASSERT_TRUE(simulate_lpv<double>(r.u.data(), n, ts, ex.a, ex.basis_a, ex.b,
                                   ex.basis_b, r.chi.data())
                  .ok());
  // v = e / (1 - q^-1 + 0.2 q^-2).
  std::mt19937 rng(9);
  std::normal_distribution<double> g(0, 0.01);
  std::vector<double> y(n);
  double v1 = 0, v2 = 0;
  for (int k = 0; k < n; ++k) {
    const double v = g(rng) + v1 - 0.2 * v2;
    v2 = v1;
    v1 = v;
    y[k] = r.chi[k] + v;
  }
  LpvProblem<double> problem{y.data(),   r.u.data(), n, ts,
                             ex.basis_a, ex.basis_b, 0, 2};
  LpvResult<double> result;
  ASSERT_TRUE(
      lpv_refined_iv<double>(problem, LpvSettings<double>(), &result).ok());
  ASSERT_EQ(result.d.size(), 3);
  EXPECT_NEAR(result.d(1), -1.0, 0.05);
  EXPECT_NEAR(result.d(2), 0.2, 0.05);
  EXPECT_NEAR(result.cost, 1e-4, 1e-5);
  EXPECT_LT((result.a - ex.a).norm(), 0.1 * ex.a.norm());
  EXPECT_LT((result.b - ex.b).norm(), 0.1 * ex.b.norm());
}

// Fast sampling (Ts = 0.001 s, 300 samples per time constant of the
// fastest frozen pole) at 10 dB: the least-squares start with a wide
// prefilter gives an unstable auxiliary model; the start chosen on the
// cut-off grid by its simulation fit does not.
TEST(LpvRefinedIvTest, FastSamplingWithNoise) {
  const double ts = 0.001;
  const int n = 30001;
  std::vector<double> u(n), p(n), chi(n), y(n);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (int k = 0; k < n; ++k) {
    if (k % 4 == 0) u[k] = uni(rng);
    if (k % 4 != 0) u[k] = u[k - 1];
    p[k] = std::sin(2 * M_PI * k * ts / 3);
  }
  Example ex(p);
  ASSERT_TRUE(simulate_lpv<double>(u.data(), n, ts, ex.a, ex.basis_a, ex.b,
                                   ex.basis_b, chi.data())
                  .ok());
  double power = 0;
  for (double v : chi) power += v * v / n;
  std::normal_distribution<double> g(0, std::sqrt(power * 0.1));  // 10 dB
  for (int k = 0; k < n; ++k) y[k] = chi[k] + g(rng);
  LpvProblem<double> problem{y.data(),   u.data(),   n, ts,
                             ex.basis_a, ex.basis_b, 0, 0};
  LpvResult<double> result;
  ASSERT_TRUE(
      lpv_refined_iv<double>(problem, LpvSettings<double>(), &result).ok());
  EXPECT_TRUE(result.converged);
  EXPECT_LT((result.a - ex.a).norm(), 0.05 * ex.a.norm());
  EXPECT_LT((result.b - ex.b).norm(), 0.05 * ex.b.norm());
}

TEST(LpvRefinedIvTest, RefusesAnUnstableInitialModel) {
  const double ts = 0.005;
  const int n = 2001;
  Record r = example_record(n, ts, 8);
  Example ex(r.p);
  ASSERT_TRUE(simulate_lpv<double>(r.u.data(), n, ts, ex.a, ex.basis_a, ex.b,
                                   ex.basis_b, r.chi.data())
                  .ok());
  LpvProblem<double> problem{r.chi.data(), r.u.data(), n, ts,
                             ex.basis_a,   ex.basis_b, 0, 0};
  LpvSettings<double> settings;
  settings.a_init = ex.a;
  settings.a_init(2, 0) = -50;  // a2 = -50 + 3 rho: a pole near +7
  settings.b_init = ex.b;
  LpvResult<double> result;
  EXPECT_EQ(lpv_refined_iv<double>(problem, settings, &result).code(),
            ErrorCode::kNumericalFailure);
  // From the true model the iteration stays there.
  settings.a_init = ex.a;
  ASSERT_TRUE(lpv_refined_iv<double>(problem, settings, &result).ok());
  EXPECT_EQ(result.iterations, 1);
  EXPECT_LT((result.a - ex.a).norm(), 1e-8 * ex.a.norm());
}

TEST(LpvRefinedIvTest, ReportsBadInput) {
  const double ts = 0.005;
  const int n = 1000;
  Record r = example_record(n, ts, 5);
  Example ex(r.p);
  LpvResult<double> result;
  std::vector<double> y(n, 0.0);
  // Scheduling data of the wrong length.
  LpvBasis<double> short_a = ex.basis_a;
  short_a.num_samples = n - 1;
  LpvProblem<double> wrong{y.data(), r.u.data(), n, ts,
                           short_a,  ex.basis_b, 0, 0};
  EXPECT_EQ(
      lpv_refined_iv<double>(wrong, LpvSettings<double>(), &result).code(),
      ErrorCode::kDimensionMismatch);
  // No excitation: u = 0.
  std::vector<double> zero(n, 0.0);
  LpvProblem<double> flat{y.data(),   zero.data(), n, ts,
                          ex.basis_a, ex.basis_b,  0, 0};
  EXPECT_EQ(lpv_refined_iv<double>(flat, LpvSettings<double>(), &result).code(),
            ErrorCode::kNumericalFailure);
  // A constant scheduling signal: the basis functions of a coefficient are
  // collinear.
  std::vector<double> p_const(n, 0.3), chi(n);
  Example flat_p(p_const);
  ASSERT_TRUE(simulate_lpv<double>(r.u.data(), n, ts, ex.a, flat_p.basis_a,
                                   ex.b, flat_p.basis_b, chi.data())
                  .ok());
  LpvProblem<double> collinear{chi.data(),     r.u.data(),     n, ts,
                               flat_p.basis_a, flat_p.basis_b, 0, 0};
  EXPECT_EQ(
      lpv_refined_iv<double>(collinear, LpvSettings<double>(), &result).code(),
      ErrorCode::kNumericalFailure);
  // Model sizes that do not match the bases.
  Eigen::MatrixXd bad_a = Eigen::MatrixXd::Ones(2, 3);
  EXPECT_EQ(simulate_lpv<double>(r.u.data(), n, ts, bad_a, ex.basis_a, ex.b,
                                 ex.basis_b, chi.data())
                .code(),
            ErrorCode::kDimensionMismatch);
}

}  // namespace
}  // namespace ctid
