// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/filters/svf.hpp and discretization.hpp against
// independent computations: analytic step responses, fine-step Runge-Kutta
// integration, the closed-form Tustin recursion and the balanced
// trapezoidal form of thesis eq. (A.7).
#include "ctid/filters/svf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_util.hpp"

namespace ctid {
namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Step response of (lambda/(p+lambda))^n and its first derivative.
double step_response(int n, double lambda, double t) {
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += std::pow(lambda * t, i) / factorial(i);
  return 1 - std::exp(-lambda * t) * sum;
}
double step_response_derivative(int n, double lambda, double t) {
  return std::pow(lambda, n) * std::pow(t, n - 1) * std::exp(-lambda * t) /
         factorial(n - 1);
}

TEST(Svf, DenominatorIsBinomialExpansion) {
  const Eigen::VectorXd d = svf_denominator<double>(3, 2.0);
  EXPECT_TRUE(test::MatrixNear(d, Eigen::Vector3d(6, 12, 8), 1e-15));
  EXPECT_DOUBLE_EQ(svf_gain<double>(3, 2.0, true), 8.0);
  EXPECT_DOUBLE_EQ(svf_gain<double>(3, 2.0, false), 1.0);
}

// A step is piecewise constant, so the ZOH filter is exact at the samples.
TEST(Svf, ZohStepResponseMatchesAnalytic) {
  const int n = 3;
  const double lambda = 2.5, h = 0.05;
  StateVariableFilter<double> svf(n, InterSample::kZoh);
  svf.set_denominator(svf_denominator<double>(n, lambda),
                      svf_gain<double>(n, lambda, true));
  double worst0 = 0, worst1 = 0;
  for (int k = 0; k < 400; ++k) {
    svf.step(1.0, h);
    const double t = k * h;
    worst0 = std::max(worst0,
                      std::abs(svf.outputs()(0) - step_response(n, lambda, t)));
    worst1 = std::max(worst1, std::abs(svf.outputs()(1) -
                                       step_response_derivative(n, lambda, t)));
  }
  EXPECT_LT(worst0, 1e-12);
  EXPECT_LT(worst1, 1e-12);
}

// p^n F s = lambda^n (s - sum d_i p^(n-i) w): check the identity
// D(p) [F s] = g s on the outputs at every sample.
TEST(Svf, OutputsSatisfyTheFilterEquation) {
  const int n = 2;
  const double lambda = 4, h = 0.01;
  const Eigen::VectorXd d = svf_denominator<double>(n, lambda);
  const double g = svf_gain<double>(n, lambda, true);
  for (InterSample is :
       {InterSample::kZoh, InterSample::kFoh, InterSample::kTrapezoid}) {
    StateVariableFilter<double> svf(n, is);
    svf.set_denominator(d, g);
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    for (int k = 0; k < 200; ++k) {
      const double s = normal(rng);
      svf.step(s, h);
      const Eigen::VectorXd& o = svf.outputs();
      EXPECT_NEAR(o(2) + d(0) * o(1) + d(1) * o(0), g * s, 1e-9 * g);
    }
  }
}

// Runge-Kutta 4 on the companion form with many sub-steps, input held.
Eigen::VectorXd rk4_hold(const Eigen::MatrixXd& F, const Eigen::VectorXd& G,
                         Eigen::VectorXd z, double s, double h, int steps) {
  const double dt = h / steps;
  auto f = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return F * x + G * s;
  };
  for (int i = 0; i < steps; ++i) {
    const Eigen::VectorXd k1 = f(z);
    const Eigen::VectorXd k2 = f(z + dt / 2 * k1);
    const Eigen::VectorXd k3 = f(z + dt / 2 * k2);
    const Eigen::VectorXd k4 = f(z + dt * k3);
    z += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return z;
}

TEST(Svf, ZohMatchesFineStepIntegrationWithIrregularSampling) {
  const int n = 3;
  const double lambda = 3;
  const Eigen::VectorXd d = svf_denominator<double>(n, lambda);
  StateVariableFilter<double> svf(n, InterSample::kZoh);
  svf.set_denominator(d, 1.0);
  const Eigen::MatrixXd F = companion_matrix<double>(d);
  Eigen::VectorXd G = Eigen::VectorXd::Zero(n);
  G(n - 1) = 1;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> interval(0.01, 0.2);
  std::normal_distribution<double> normal;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  double s_prev = 0;
  for (int k = 0; k < 100; ++k) {
    const double h = interval(rng);
    const double s = normal(rng);
    if (k > 0) z = rk4_hold(F, G, z, s_prev, h, 2000);
    svf.step(s, h);
    s_prev = s;
    EXPECT_TRUE(test::MatrixNear(svf.state(), z, 1e-11)) << "sample " << k;
  }
}

// First order lambda/(p + lambda) by Tustin:
//   y_k = a y_(k-1) + b (s_k + s_(k-1)), a = (2 - lh)/(2 + lh), b = lh/(2 +
//   lh).
TEST(Svf, TrapezoidalMatchesClosedFormTustin) {
  const double lambda = 5, h = 0.02;
  StateVariableFilter<double> svf(1, InterSample::kTrapezoid);
  svf.set_denominator(svf_denominator<double>(1, lambda), lambda);
  const double a = (2 - lambda * h) / (2 + lambda * h);
  const double b = lambda * h / (2 + lambda * h);
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  double y = 0, s_prev = 0;
  for (int k = 0; k < 500; ++k) {
    const double s = normal(rng);
    y = k == 0 ? b * s : a * y + b * (s + s_prev);
    s_prev = s;
    svf.step(s, h);
    ASSERT_NEAR(svf.outputs()(0), y, 1e-13) << "sample " << k;
  }
}

// Thesis eq. (A.7), balanced coordinates, gives the same outputs as the
// physical-coordinate form used by the filter.
TEST(Svf, TrapezoidalMatchesThesisEquationA7) {
  const int n = 2;
  const double lambda = 3, h = 0.05;
  const Eigen::VectorXd d = svf_denominator<double>(n, lambda);
  const double g = svf_gain<double>(n, lambda, true);
  const Eigen::MatrixXd F = companion_matrix<double>(d);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, 1);
  G(n - 1, 0) = 1;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n + 1, n);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + 1, 1);
  H.topRows(n) = g * Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < n; ++i) H(n, i) = -g * d(n - 1 - i);
  J(n, 0) = g;
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd inv = (I - h / 2 * F).inverse();
  const Eigen::MatrixXd Fd = (I + h / 2 * F) * inv;
  const Eigen::MatrixXd Gd = std::sqrt(h) * inv * G;
  const Eigen::MatrixXd Hd = std::sqrt(h) * H * inv;
  const Eigen::MatrixXd Jd = J + h / 2 * H * inv * G;

  StateVariableFilter<double> svf(n, InterSample::kTrapezoid);
  svf.set_denominator(d, g);
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 300; ++k) {
    const double s = normal(rng);
    const Eigen::VectorXd y = Hd * x + Jd * s;
    x = Fd * x + Gd * s;
    svf.step(s, h);
    ASSERT_TRUE(test::MatrixNear(svf.outputs(), y, 1e-11)) << "sample " << k;
  }
}

// A denominator switched mid-record keeps the state: compare with RK4 on
// the piecewise-constant system.
TEST(Svf, TimeVaryingDenominatorCarriesState) {
  const int n = 2;
  const double h = 0.1;
  StateVariableFilter<double> svf(n, InterSample::kZoh);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd G = Eigen::VectorXd::Zero(n);
  G(n - 1) = 1;
  double s_prev = 0;
  for (int k = 0; k < 120; ++k) {
    const Eigen::Vector2d d(1.0 + 0.01 * k, 2.0 + 0.02 * k);
    svf.set_denominator(d, 1.0);
    const double s = std::sin(0.3 * k);
    if (k > 0) z = rk4_hold(companion_matrix<double>(d), G, z, s_prev, h, 500);
    svf.step(s, h);
    s_prev = s;
    ASSERT_TRUE(test::MatrixNear(svf.state(), z, 1e-10)) << "sample " << k;
  }
}

TEST(Svf, RunsInSinglePrecision) {
  const int n = 2;
  const float lambda = 2, h = 0.05f;
  StateVariableFilter<float> svf(n, InterSample::kZoh);
  svf.set_denominator(svf_denominator<float>(n, lambda),
                      svf_gain<float>(n, lambda, true));
  for (int k = 0; k < 200; ++k) {
    svf.step(1.0f, h);
    EXPECT_NEAR(svf.outputs()(0), step_response(n, lambda, k * h), 2e-6);
  }
}

}  // namespace
}  // namespace ctid
