// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/adaptation/qn_ml.hpp and nlopt_minimizer.hpp: the cost
// (3.23) with sigma_e^2 concentrated out against its definition, the
// search's checks, and the ML estimate of Qn recovering the random-walk
// variance that generated a regression (sec. 3.3, model 3.12).
#include "ctid/adaptation/qn_ml.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/adaptation/nlopt_minimizer.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

// V(sigma^2) = sum log(sigma^2 rho) + sum e^2 / (sigma^2 rho), eq. (3.23).
double cost_at(const std::vector<double>& e, const std::vector<double>& rho,
               double sigma2) {
  double v = 0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (std::isnan(rho[k])) continue;
    v += std::log(sigma2 * rho[k]) + e[k] * e[k] / (sigma2 * rho[k]);
  }
  return v;
}

TEST(QnMl, ConcentratedCostIsTheMinimumOverSigma) {
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  std::vector<double> e(400), rho(400);
  for (std::size_t k = 0; k < e.size(); ++k) {
    rho[k] = 1 + std::abs(normal(rng));
    e[k] = 0.3 * std::sqrt(rho[k]) * normal(rng);
  }
  rho[7] = NAN;  // a sample without an update is skipped
  const InnovationLikelihood l =
      concentrated_likelihood(e.data(), rho.data(), e.size());
  EXPECT_EQ(l.samples, 399);
  EXPECT_NEAR(l.cost, cost_at(e, rho, l.sigma2), 1e-9 * std::abs(l.cost));
  for (double f : {0.5, 0.9, 0.99, 1.01, 1.1, 2.0}) {
    EXPECT_LT(l.cost, cost_at(e, rho, f * l.sigma2));
  }
  rho[3] = -1;  // a diverged filter
  EXPECT_TRUE(
      std::isinf(concentrated_likelihood(e.data(), rho.data(), e.size()).cost));
}

TEST(QnMl, SearchSettingsAreChecked) {
  QnSearchSettings s;
  s.q0 = {1e-3, 0};
  s.lower = {1e-5, 0};
  s.upper = {1e-1, 0};
  s.free = {true, false};
  EXPECT_TRUE(validate_qn_search(s, 2).ok());
  EXPECT_EQ(validate_qn_search(s, 3).code(), ErrorCode::kDimensionMismatch);
  QnSearchSettings c = s;
  c.lower[0] = 1;  // bounds cross
  EXPECT_EQ(validate_qn_search(c, 2).code(), ErrorCode::kBadInput);
  c = s;
  c.lower[0] = 0;  // log scale
  EXPECT_EQ(validate_qn_search(c, 2).code(), ErrorCode::kBadInput);
  c = s;
  c.q0[0] = 1;  // start outside the bounds
  EXPECT_EQ(validate_qn_search(c, 2).code(), ErrorCode::kBadInput);
  c = s;
  c.lower[1] = 1e-6;
  c.upper[1] = 1e-4;  // the fixed 0 lies outside its own bounds
  EXPECT_EQ(validate_qn_search(c, 2).code(), ErrorCode::kBadInput);
  c = s;
  c.free = {false, false};
  EXPECT_EQ(validate_qn_search(c, 2).code(), ErrorCode::kBadInput);
  c = s;
  c.q0[1] = -1;
  EXPECT_EQ(validate_qn_search(c, 2).code(), ErrorCode::kBadInput);
}

// Model (3.12): theta_k = theta_(k-1) + w_k, z_k = psi_k^T theta_k + e_k,
// with Qw = diag(q) sigma_e^2. The Kalman filter with Qn = diag(q') gives
// the exact likelihood of q', so its maximiser estimates q: with 20000
// samples the estimate of the drifting element lands within a factor 1.5
// of the truth (the spread of the ML estimate at this N is ~10-20 %, see
// the second check), and the constant element, left free, goes to its
// lower bound.
TEST(QnMl, RecoversTheRandomWalkVarianceOfARegression) {
  const int n = 20000;
  const double sigma = 0.1;
  const double q_true = 1e-4;  // normalised: Qw = q sigma^2
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd psi(2, n);
  std::vector<double> z(n);
  Eigen::Vector2d theta(1, 2);
  for (int k = 0; k < n; ++k) {
    psi(0, k) = normal(rng);
    psi(1, k) = normal(rng);
    theta(0) += std::sqrt(q_true) * sigma * normal(rng);
    z[k] = psi.col(k).dot(theta) + sigma * normal(rng);
  }
  auto cost = [&](const std::vector<double>& q, double* sigma2) {
    Eigen::Matrix2d Qn = Eigen::Vector2d(q[0], q[1]).asDiagonal();
    ParameterUpdate<double> kf(2, KalmanAdaptation<double>(Qn));
    kf.reset(Eigen::Vector2d::Zero(), 1e4 * Eigen::Matrix2d::Identity());
    std::vector<double> e(n), rho(n);
    for (int k = 0; k < n; ++k) {
      e[k] = kf.update(psi.col(k), z[k]);
      rho[k] = kf.innovation_scale();
    }
    const InnovationLikelihood l =
        concentrated_likelihood(e.data(), rho.data(), n);
    if (sigma2) *sigma2 = l.sigma2;
    return l.cost;
  };
  QnSearchSettings s;
  s.q0 = {1e-5, 1e-5};
  s.lower = {1e-8, 1e-8};
  s.upper = {1e-1, 1e-1};
  s.free = {true, true};
  QnSearchResult result;
  ASSERT_TRUE(estimate_qn_diagonal(cost, s, nlopt_minimize, result).ok());
  RecordProperty("q_hat", test::scientific(result.q[0]));
  EXPECT_TRUE(result.converged) << result.message;
  EXPECT_GT(result.q[0], q_true / 1.5);
  EXPECT_LT(result.q[0], q_true * 1.5);
  EXPECT_LT(result.q[1], 1e-6);
  EXPECT_NEAR(std::sqrt(result.sigma2), sigma, 0.05 * sigma);
  // The optimum is no worse than a grid around it.
  for (double f : {0.5, 0.8, 1.25, 2.0}) {
    EXPECT_LE(result.cost, cost({result.q[0] * f, result.q[1]}, nullptr) +
                               1e-9 * std::abs(result.cost));
  }
  // One free element (COBYLA), the other fixed at 0: the same optimum.
  s.free = {true, false};
  s.q0 = {1e-5, 0};
  s.lower = {1e-8, 0};  // the fixed element's own bounds must hold 0
  QnSearchResult one;
  ASSERT_TRUE(estimate_qn_diagonal(cost, s, nlopt_minimize, one).ok());
  EXPECT_EQ(one.q[1], 0.0);
  EXPECT_NEAR(std::log10(one.q[0]), std::log10(result.q[0]), 0.05);
}

}  // namespace
}  // namespace ctid
