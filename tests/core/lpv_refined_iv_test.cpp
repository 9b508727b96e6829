// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/simulation/lpv_simulator.hpp and
// core/include/ctid/offline/lpv_refined_iv.hpp: the Euler LPV simulator
// against a fine-step Runge-Kutta integration of the LPV differential
// equation (first-order convergence), exact recovery of an LPV model from
// its noise-free output, consistency under noise, and the errors.
#include "ctid/offline/lpv_refined_iv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace ctid {
namespace {

// The system of CONTSID's LPV example:
//   y'' + a1(p) y' + a2(p) y = b1(p) u' + b0(p) u,
//   a1 = 2 - 1.5p + 2p^2, a2 = 5 + 3p, b1 = 3 + 2cos(p), b0 = 5 - 3 sin(2p).
struct Example {
  Eigen::MatrixXd a{{1, 0, 0}, {2, -1.5, 2}, {5, 3, 0}};
  Eigen::MatrixXd b{{3, 2}, {5, -3}};
  std::vector<double> dep_a, dep_b;
  LpvBasis<double> basis_a, basis_b;

  explicit Example(const std::vector<double>& p) {
    const Eigen::Index n = static_cast<Eigen::Index>(p.size());
    dep_a.resize(3 * 2 * n);
    dep_b.resize(2 * 2 * n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const double r = p[k];
      const double fa[6] = {1, r, r * r, 1, r, 0};
      for (int q = 0; q < 6; ++q) dep_a[6 * k + q] = fa[q];
      const double fb[4] = {1, std::cos(r), 1, std::sin(2 * r)};
      for (int q = 0; q < 4; ++q) dep_b[4 * k + q] = fb[q];
    }
    basis_a = {dep_a.data(), 3, 2, n};
    basis_b = {dep_b.data(), 2, 2, n};
  }
};

double rho(double t) { return std::sin(2 * M_PI * t / 3); }
double u_smooth(double t) { return std::sin(1.3 * t) + 0.5 * std::sin(3.1 * t); }
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
  ASSERT_TRUE(simulate_lpv<double>(u.data(), n, ts, a, ba, b, bb, y.data())
                  .ok());
  double prev = 0;
  for (int k = 0; k < n; ++k) {
    const double expected = (prev / ts + 3 * u[k]) / (1 / ts + 2);
    EXPECT_NEAR(y[k], expected, 1e-12);
    prev = expected;
  }
}

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
  LpvProblem<double> problem{y.data(), r.u.data(), n, ts,
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
  LpvProblem<double> problem{y.data(), r.u.data(), n, ts,
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
  LpvProblem<double> wrong{y.data(), r.u.data(), n, ts, short_a, ex.basis_b,
                           0, 0};
  EXPECT_EQ(lpv_refined_iv<double>(wrong, LpvSettings<double>(), &result)
                .code(),
            ErrorCode::kDimensionMismatch);
  // No excitation: u = 0.
  std::vector<double> zero(n, 0.0);
  LpvProblem<double> flat{y.data(), zero.data(), n, ts, ex.basis_a,
                          ex.basis_b, 0, 0};
  EXPECT_EQ(
      lpv_refined_iv<double>(flat, LpvSettings<double>(), &result).code(),
      ErrorCode::kNumericalFailure);
  // A constant scheduling signal: the basis functions of a coefficient are
  // collinear.
  std::vector<double> p_const(n, 0.3), chi(n);
  Example flat_p(p_const);
  ASSERT_TRUE(simulate_lpv<double>(r.u.data(), n, ts, ex.a, flat_p.basis_a,
                                   ex.b, flat_p.basis_b, chi.data())
                  .ok());
  LpvProblem<double> collinear{chi.data(), r.u.data(), n, ts,
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
