// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/simulation/lpv_simulator.hpp: the Euler LPV
// simulator against a fine-step Runge-Kutta integration of the LPV
// differential equation (first-order convergence), and a time-invariant
// model against its Euler difference equation.
#include "ctid/simulation/lpv_simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "lpv_example.hpp"

namespace ctid {
namespace {

using test::Example;

double rho(double t) { return std::sin(2 * M_PI * t / 3); }
double u_smooth(double t) {
  return std::sin(1.3 * t) + 0.5 * std::sin(3.1 * t);
}
double du_smooth(double t) {
  return 1.3 * std::cos(1.3 * t) + 1.55 * std::cos(3.1 * t);
}

// y at t = k Ts by RK4 with step Ts/sub of the state [y, y'].
std::vector<double> rk4_reference(double ts, int n, int sub) {
  auto f = [](double t, const Eigen::Vector2d& x) {
    const double p = rho(t);
    const double a1 = 2 - 1.5 * p + 2 * p * p, a2 = 5 + 3 * p;
    const double b1 = 3 + 2 * std::cos(p), b0 = 5 - 3 * std::sin(2 * p);
    return Eigen::Vector2d(
        x(1), -a1 * x(1) - a2 * x(0) + b1 * du_smooth(t) + b0 * u_smooth(t));
  };
  std::vector<double> y(n);
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  const double h = ts / sub;
  double t = 0;
  y[0] = 0;
  for (int k = 1; k < n; ++k) {
    for (int s = 0; s < sub; ++s) {
      const Eigen::Vector2d k1 = f(t, x);
      const Eigen::Vector2d k2 = f(t + h / 2, x + h / 2 * k1);
      const Eigen::Vector2d k3 = f(t + h / 2, x + h / 2 * k2);
      const Eigen::Vector2d k4 = f(t + h, x + h * k3);
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      t += h;
    }
    y[k] = x(0);
  }
  return y;
}

double euler_error(double ts, double t_end) {
  const int n = static_cast<int>(std::lround(t_end / ts)) + 1;
  std::vector<double> u(n), p(n), y(n);
  for (int k = 0; k < n; ++k) {
    u[k] = u_smooth(k * ts);
    p[k] = rho(k * ts);
  }
  Example ex(p);
  EXPECT_TRUE(simulate_lpv<double>(u.data(), n, ts, ex.a, ex.basis_a, ex.b,
                                   ex.basis_b, y.data())
                  .ok());
  const std::vector<double> ref = rk4_reference(ts, n, 20);
  double err = 0, peak = 0;
  for (int k = 0; k < n; ++k) {
    err = std::max(err, std::abs(y[k] - ref[k]));
    peak = std::max(peak, std::abs(ref[k]));
  }
  return err / peak;
}

TEST(LpvSimulatorTest, ConvergesToTheDifferentialEquationAtFirstOrder) {
  const double e1 = euler_error(0.01, 10);
  const double e2 = euler_error(0.005, 10);
  const double e4 = euler_error(0.0025, 10);
  EXPECT_LT(e1, 0.05);
  EXPECT_LT(e4, 0.0125);
  // Backward Euler: halving Ts halves the error.
  EXPECT_NEAR(e1 / e2, 2.0, 0.3);
  EXPECT_NEAR(e2 / e4, 2.0, 0.3);
}

TEST(LpvSimulatorTest, TimeInvariantModelMatchesTheEulerDifferenceEquation) {
  // y' + 2 y = 3 u: (y_k - y_(k-1))/Ts + 2 y_k = 3 u_k.
  const int n = 50;
  const double ts = 0.1;
  std::vector<double> u(n), y(n), dep(n, 1.0);
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (double& v : u) v = g(rng);
  LpvBasis<double> ba{dep.data(), 1, 1, n}, bb{dep.data(), 1, 1, n};
  Eigen::MatrixXd a{{1}, {2}}, b{{3}};
  ASSERT_TRUE(
      simulate_lpv<double>(u.data(), n, ts, a, ba, b, bb, y.data()).ok());
  double prev = 0;
  for (int k = 0; k < n; ++k) {
    const double expected = (prev / ts + 3 * u[k]) / (1 / ts + 2);
    EXPECT_NEAR(y[k], expected, 1e-12);
    prev = expected;
  }
}

TEST(LpvSimulatorTest, ReportsBadModels) {
  const int n = 100;
  std::vector<double> u(n, 1.0), y(n), p(n, 0.0);
  Example ex(p);
  Eigen::MatrixXd bad_a = Eigen::MatrixXd::Ones(2, 3);
  EXPECT_EQ(simulate_lpv<double>(u.data(), n, 0.01, bad_a, ex.basis_a, ex.b,
                                 ex.basis_b, y.data())
                .code(),
            ErrorCode::kDimensionMismatch);
  Eigen::MatrixXd varying_lead = ex.a;
  varying_lead(0, 1) = 1;
  EXPECT_EQ(simulate_lpv<double>(u.data(), n, 0.01, varying_lead, ex.basis_a,
                                 ex.b, ex.basis_b, y.data())
                .code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(simulate_lpv<double>(u.data(), n - 1, 0.01, ex.a, ex.basis_a, ex.b,
                                 ex.basis_b, y.data())
                .code(),
            ErrorCode::kDimensionMismatch);
}

}  // namespace
}  // namespace ctid
