// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/pde_heat.hpp: the Crank-Nicolson heat
// simulator against the separable exact solution (second-order convergence)
// and against an RK4 integration of the method of lines, the 2-D filter
// against one-dimensional recursions written out, the noise-free recovery
// of [a b] by LSSVF, SRIVC and RIVC, the noise model of RIVC, and the
// statuses on bad input.
#include "ctid/offline/pde_heat.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_util.hpp"

namespace ctid {
namespace {

Eigen::VectorXd grid(double lo, double step, long n) {
  return Eigen::VectorXd::LinSpaced(n, lo, lo + step * (n - 1));
}

// A source pulse train at one node and a sine at another.
Eigen::MatrixXd example_input(const Eigen::VectorXd& t, long nx) {
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(t.size(), nx);
  for (long k = 0; k < t.size(); ++k) {
    u(k, nx / 2) = std::fmod(t[k], 400.0) < 200.0 ? 0.01 : 0.0;
    u(k, nx / 4) = 0.004 * std::sin(t[k] / 60.0);
  }
  return u;
}

// y(k) = sum b_i x(k-i) - sum_{i>0} a_i y(k-i), along one sequence.
std::vector<double> filter1(const std::vector<double>& b,
                            const std::vector<double>& a,
                            const std::vector<double>& x) {
  std::vector<double> y(x.size(), 0.0);
  for (std::size_t k = 0; k < x.size(); ++k) {
    double s = 0.0;
    for (std::size_t i = 0; i < b.size() && i <= k; ++i) s += b[i] * x[k - i];
    for (std::size_t i = 1; i < a.size() && i <= k; ++i) s -= a[i] * y[k - i];
    y[k] = s / a[0];
  }
  return y;
}

TEST(Filter2d, SeparableEqualsRowThenColumnRecursions) {
  std::mt19937 rng(1);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd x(40, 12);
  for (long i = 0; i < x.size(); ++i) x.data()[i] = n01(rng);
  const std::vector<double> b1{1, 0.5}, a1{1, -1.2, 0.4}, b2{2, -1, 0.3},
      a2{1, -0.3};
  Eigen::MatrixXd num(2, 3), den(3, 2);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) num(i, j) = b1[i] * b2[j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) den(i, j) = a1[i] * a2[j];
  Eigen::MatrixXd y;
  ASSERT_TRUE(filter_2d(num, den, x, &y).ok());
  Eigen::MatrixXd ref = x;
  for (long j = 0; j < x.cols(); ++j) {
    std::vector<double> c(x.rows());
    for (long i = 0; i < x.rows(); ++i) c[i] = ref(i, j);
    c = filter1(b1, a1, c);
    for (long i = 0; i < x.rows(); ++i) ref(i, j) = c[i];
  }
  for (long i = 0; i < x.rows(); ++i) {
    std::vector<double> r(x.cols());
    for (long j = 0; j < x.cols(); ++j) r[j] = ref(i, j);
    r = filter1(b2, a2, r);
    for (long j = 0; j < x.cols(); ++j) ref(i, j) = r[j];
  }
  EXPECT_TRUE(test::MatrixNear(y, ref, 1e-12));
}

TEST(SimulateHeat, SecondOrderConvergenceToTheSeparableSolution) {
  const double a = 0.1;
  double err[2];
  for (int r = 0; r < 2; ++r) {
    const long nx = 20 * (r + 1) + 1;
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(nx, 0.0, 1.0);
    const double h = 0.02 / (r + 1);
    const long nt = static_cast<long>(std::lround(0.5 / h)) + 1;
    const Eigen::VectorXd t = grid(0.0, h, nt);
    Eigen::VectorXd ic = (M_PI * x).array().sin();
    Eigen::MatrixXd y;
    ASSERT_TRUE(simulate_heat(a, 3.0, t, x, Eigen::MatrixXd::Zero(nt, nx),
                              ic, &y)
                    .ok());
    err[r] = 0.0;
    for (long k = 0; k < nt; ++k)
      for (long i = 0; i < nx; ++i)
        err[r] = std::max(err[r], std::abs(y(k, i) - std::exp(-a * M_PI *
                                                              M_PI * t[k]) *
                                                         ic[i]));
  }
  EXPECT_LT(err[0], 2e-3);
  EXPECT_GT(err[0] / err[1], 3.5) << err[0] << " " << err[1];
  EXPECT_LT(err[0] / err[1], 4.5) << err[0] << " " << err[1];
}

TEST(SimulateHeat, MatchesRk4MethodOfLinesOnANonUniformGrid) {
  Eigen::VectorXd x(7);
  x << 0, 0.15, 0.3, 0.4, 0.6, 0.8, 1.0;
  const long nx = x.size(), n = nx - 2;
  const double a = 0.05, b = -2.0, h = 1e-3;
  const long nt = 401;
  const Eigen::VectorXd t = grid(0.0, h, nt);
  auto src = [&](double tt, double xx) {
    return std::sin(3 * tt) * std::exp(-20 * (xx - 0.4) * (xx - 0.4));
  };
  Eigen::MatrixXd u(nt, nx);
  for (long k = 0; k < nt; ++k)
    for (long i = 0; i < nx; ++i) u(k, i) = src(t[k], x[i]);
  Eigen::VectorXd ic = (x.array() * (1 - x.array())).matrix();
  Eigen::MatrixXd y;
  ASSERT_TRUE(simulate_heat(a, b, t, x, u, ic, &y).ok());
  // Method of lines, dense second-difference matrix, RK4 with 20 substeps.
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  for (long i = 0; i < n; ++i) {
    const double hl = x[i + 1] - x[i], hr = x[i + 2] - x[i + 1];
    if (i > 0) L(i, i - 1) = 2 / (hl * (hl + hr));
    L(i, i) = -2 / (hl * hr);
    if (i + 1 < n) L(i, i + 1) = 2 / (hr * (hl + hr));
  }
  auto f = [&](double tt, const Eigen::VectorXd& z) {
    Eigen::VectorXd s(n);
    for (long i = 0; i < n; ++i) s[i] = b * src(tt, x[i + 1]);
    return Eigen::VectorXd(a * L * z + s);
  };
  Eigen::VectorXd z = ic.segment(1, n);
  const int sub = 20;
  const double dt = h / sub;
  double tt = 0.0, worst = 0.0, scale = 0.0;
  for (long k = 1; k < nt; ++k) {
    for (int s = 0; s < sub; ++s) {
      const Eigen::VectorXd k1 = f(tt, z);
      const Eigen::VectorXd k2 = f(tt + dt / 2, z + dt / 2 * k1);
      const Eigen::VectorXd k3 = f(tt + dt / 2, z + dt / 2 * k2);
      const Eigen::VectorXd k4 = f(tt + dt, z + dt * k3);
      z += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      tt += dt;
    }
    worst = std::max(worst, (y.row(k).segment(1, n).transpose() - z)
                                .cwiseAbs()
                                .maxCoeff());
    scale = std::max(scale, z.cwiseAbs().maxCoeff());
  }
  // Crank-Nicolson's error, O(h^2) with h = 1e-3, relative to the field.
  EXPECT_LT(worst, 1e-5 * scale) << worst << " vs scale " << scale;
}

struct Example {
  Eigen::VectorXd t = grid(0.0, 2.0, 601), x = grid(0.0, 0.05, 21);
  Eigen::MatrixXd u = example_input(t, x.size());
  Eigen::Vector2d theta{5e-4, 0.7};
  Eigen::MatrixXd y;
  Example() {
    simulate_heat(theta[0], theta[1], t, x, u, Eigen::VectorXd::Zero(x.size()),
                  &y);
  }
};

TEST(HeatLssvf, BilinearRecoversNoiseFreeParametersExactly) {
  const Example ex;
  for (double lt : {0.05, 1.0}) {
    Eigen::Vector2d th;
    ASSERT_TRUE(heat_lssvf(ex.t, ex.x, ex.y, ex.u, HeatRule::kBilinear, lt,
                           5.0, &th)
                    .ok());
    EXPECT_LT(((th - ex.theta).array() / ex.theta.array()).abs().maxCoeff(),
              1e-8)
        << th.transpose();
  }
  Eigen::Vector2d th;
  ASSERT_TRUE(heat_lssvf(ex.t, ex.x, ex.y, ex.u, HeatRule::kEuler, 0.05, 5.0,
                         &th)
                  .ok());
  EXPECT_LT(std::abs(th[0] / ex.theta[0] - 1), 0.05) << th.transpose();
}

TEST(HeatSrivc, RecoversNoiseFreeParametersAndIsCloseWithNoise) {
  Example ex;
  HeatIvResult r;
  const Eigen::VectorXd ic = Eigen::VectorXd::Zero(ex.x.size());
  ASSERT_TRUE(heat_srivc(ex.t, ex.x, ex.y, ex.u, ic, HeatIvOptions(), &r).ok());
  EXPECT_TRUE(r.converged);
  EXPECT_LT(((r.theta - ex.theta).array() / ex.theta.array()).abs().maxCoeff(),
            1e-7);
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  const double sd = std::sqrt((ex.y.array() - ex.y.mean()).square().mean());
  Eigen::MatrixXd yn = ex.y;
  for (long i = 0; i < yn.size(); ++i) yn.data()[i] += 0.3 * sd * n01(rng);
  ASSERT_TRUE(heat_srivc(ex.t, ex.x, yn, ex.u, ic, HeatIvOptions(), &r).ok());
  EXPECT_LT(((r.theta - ex.theta).array() / ex.theta.array()).abs().maxCoeff(),
            0.05)
      << r.theta.transpose();
}

TEST(HeatRivc, RecoversTheSeparableNoiseModel) {
  Example ex;
  std::mt19937 rng(11);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd e(ex.y.rows(), ex.y.cols());
  for (long i = 0; i < e.size(); ++i) e.data()[i] = n01(rng);
  Eigen::MatrixXd num = Eigen::MatrixXd::Ones(1, 1), den(3, 2);
  den << 1, -0.3, -1.2, 0.36, 0.4, -0.12;  // (1 -1.2 0.4)' * (1 -0.3)
  Eigen::MatrixXd v;
  ASSERT_TRUE(filter_2d(num, den, e, &v).ok());
  const double sd = std::sqrt((ex.y.array() - ex.y.mean()).square().mean());
  const double sv = std::sqrt((v.array() - v.mean()).square().mean());
  const Eigen::MatrixXd yn = ex.y + 0.3 * sd / sv * v;
  HeatIvOptions opt;
  opt.orders[0] = 2;
  opt.orders[2] = 1;
  HeatIvResult r;
  ASSERT_TRUE(heat_rivc(ex.t, ex.x, yn, ex.u,
                        Eigen::VectorXd::Zero(ex.x.size()), opt, &r)
                  .ok());
  EXPECT_LT(((r.theta - ex.theta).array() / ex.theta.array()).abs().maxCoeff(),
            0.05)
      << r.theta.transpose();
  ASSERT_EQ(r.dt.size(), 3);
  ASSERT_EQ(r.ds.size(), 2);
  EXPECT_NEAR(r.dt[1], -1.2, 0.05);
  EXPECT_NEAR(r.dt[2], 0.4, 0.05);
  EXPECT_NEAR(r.ds[1], -0.3, 0.05);
}

TEST(PdeHeat, BadInputIsReported) {
  const Example ex;
  Eigen::MatrixXd y;
  const Eigen::VectorXd ic = Eigen::VectorXd::Zero(ex.x.size());
  EXPECT_EQ(simulate_heat(-1.0, 1.0, ex.t, ex.x, ex.u, ic, &y).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(simulate_heat(1.0, 1.0, ex.t, ex.x, ex.u.topRows(3), ic, &y).code(),
            ErrorCode::kDimensionMismatch);
  Eigen::VectorXd xbad = ex.x;
  xbad[3] = xbad[4];
  EXPECT_EQ(simulate_heat(1.0, 1.0, ex.t, xbad, ex.u, ic, &y).code(),
            ErrorCode::kBadInput);
  Eigen::VectorXd xnu = ex.x;
  xnu[3] += 0.01;
  Eigen::Vector2d th;
  EXPECT_EQ(heat_lssvf(ex.t, xnu, ex.y, ex.u, HeatRule::kBilinear, 1, 1, &th)
                .code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(heat_lssvf(ex.t, ex.x, ex.y, ex.u, HeatRule::kBilinear, 0, 1, &th)
                .code(),
            ErrorCode::kBadOption);
  EXPECT_EQ(heat_lssvf(ex.t, ex.x, ex.y, 0 * ex.u, HeatRule::kBilinear, 1, 1,
                       &th)
                .code(),
            ErrorCode::kNumericalFailure);
  Eigen::MatrixXd out;
  EXPECT_EQ(filter_2d(Eigen::MatrixXd::Ones(1, 1),
                      Eigen::MatrixXd::Zero(1, 2), ex.y, &out)
                .code(),
            ErrorCode::kBadInput);
  HeatIvOptions bad;
  bad.maxiter = 0;
  HeatIvResult r;
  EXPECT_EQ(heat_srivc(ex.t, ex.x, ex.y, ex.u, ic, bad, &r).code(),
            ErrorCode::kBadOption);
}

}  // namespace
}  // namespace ctid
