// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/simulation/physical_realisations.hpp against
// independent computations: the linear cascade against its closed-form
// solution for inputs held over each sample (exponentials written out, no
// matrix exponential), the end stop far from its levels against the linear
// model's exact ZOH response by partial fractions (first-order modes), a
// double integrator hitting and leaving a stop against t^2/2, the
// square-root cascade's rest and overflow levels, and the steady state of a
// cascade whose overflow partly falls into its outer section.
#include "ctid/simulation/physical_realisations.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_util.hpp"

namespace ctid {
namespace {

// Levels of a random staircase, one value per sample.
std::vector<double> staircase(long n, int hold, double lo, double hi,
                              unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  std::vector<double> u(n);
  double v = dist(gen);
  for (long k = 0; k < n; ++k) {
    if (k % hold == 0) v = dist(gen);
    u[k] = v;
  }
  return u;
}

CascadeConfig<double> cascade(bool sqrt_nodes, double b, double d, double al,
                              double ga, double hi, double c, double ts,
                              int substeps) {
  CascadeConfig<double> cfg;
  cfg.sqrt_nodes = sqrt_nodes;
  cfg.b = Eigen::MatrixXd::Constant(1, 1, b);
  cfg.d = Eigen::VectorXd::Constant(1, d);
  cfg.alpha = Eigen::VectorXd::Constant(1, al);
  cfg.gamma = Eigen::VectorXd::Constant(1, ga);
  cfg.hi = Eigen::VectorXd::Constant(1, hi);
  cfg.c = Eigen::VectorXd::Constant(1, c);
  cfg.ts = ts;
  cfg.substeps = substeps;
  return cfg;
}

// z' = q - al z, h' = z - ga h, q held over [0, T]: exact.
void linear_cascade_step(double al, double ga, double q, double T, double& z,
                         double& h) {
  const double zss = q / al;
  const double ea = std::exp(-al * T);
  const double eg = std::exp(-ga * T);
  const double hn =
      eg * h + zss * (1 - eg) / ga + (z - zss) * (ea - eg) / (ga - al);
  z = ea * z + zss * (1 - ea);
  h = hn;
}

// Simulates cfg with `substeps` sub-steps into y and z (sized to u),
// expects the inner state to end at its level cfg.hi(0), and returns the
// distance of the last output from `target`.
double final_error_at_level(CascadeConfig<double>& cfg, int substeps,
                            const std::vector<double>& u, double target,
                            std::vector<double>& y, std::vector<double>& z) {
  const long n = static_cast<long>(u.size());
  cfg.substeps = substeps;
  EXPECT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y.data(), z.data()).ok());
  EXPECT_DOUBLE_EQ(z[n - 1], cfg.hi(0));
  return std::abs(y[n - 1] - target);
}

TEST(Cascade, LinearMatchesClosedForm) {
  const double al = 0.3, ga = 0.12, b = 0.8, d = 0.05, c = 1.5, ts = 1;
  const long n = 1500;
  const std::vector<double> u = staircase(n, 60, 0, 5, 7);
  std::vector<double> exact(n);
  double z = std::max(b * u[0] + d, 0.0) / al;
  double h = z / ga;
  for (long k = 0; k < n; ++k) {
    exact[k] = h + c;
    linear_cascade_step(al, ga, b * u[k] + d, ts, z, h);
  }
  double err[2];
  const int steps[2] = {10, 20};
  for (int i = 0; i < 2; ++i) {
    const CascadeConfig<double> cfg =
        cascade(false, b, d, al, ga, INFINITY, c, ts, steps[i]);
    std::vector<double> y(n);
    ASSERT_TRUE(
        simulate_cascade<double>(cfg, u.data(), n, y.data(), nullptr).ok());
    err[i] = 0;
    for (long k = 0; k < n; ++k) {
      err[i] = std::max(err[i], std::abs(y[k] - exact[k]));
    }
  }
  double range = 0;
  for (double v : exact) range = std::max(range, std::abs(v));
  EXPECT_LT(err[0], 1e-6 * range);
  // classical Runge-Kutta: fourth order, halving the step divides the
  // error by about 16
  EXPECT_GT(err[0] / err[1], 12.0);
  EXPECT_LT(err[0] / err[1], 20.0);
}

TEST(Cascade, SquareRootRestAndOverflow) {
  const double al = 0.01, ga = 0.085, b = 0.0012, ts = 2;
  const long n = 3000;  // 6000 s: 50 time constants of the outer tank
  std::vector<double> u(n, 5.0);
  // at rest for the first sample's inflow: stays there
  CascadeConfig<double> cfg = cascade(true, b, 0, al, ga, INFINITY, 0, ts, 8);
  std::vector<double> y(n), z(n);
  ASSERT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y.data(), z.data()).ok());
  const double zss = std::pow(b * 5 / al, 2);
  const double hss = std::pow(std::sqrt(zss) / ga, 2);
  for (long k = 0; k < n; ++k) {
    ASSERT_NEAR(z[k], zss, 1e-12 * zss);
    ASSERT_NEAR(y[k], hss, 1e-12 * hss);
  }
  // an inner level below the rest level: z stays at it and h tends to the
  // rest level of the inflow sqrt(hi). The projection after each step lets
  // the Runge-Kutta stages see z above the level within the step, an
  // O(h) excess of the inner outflow: the error falls with the sub-step.
  const double top = 0.5 * zss;
  const double h_top = top / (ga * ga);
  u.assign(n, 0.0);
  for (long k = 1; k < n; ++k) u[k] = 5.0;
  cfg.hi(0) = top;
  double err[2];
  const int steps[2] = {8, 64};
  for (int i = 0; i < 2; ++i) {
    err[i] = final_error_at_level(cfg, steps[i], u, h_top, y, z);
    EXPECT_EQ(z[0], 0.0);
    for (long k = 0; k < n; ++k) ASSERT_LE(z[k], top);
    std::printf("substeps %d: |h - hi/gamma^2| = %.3g\n", steps[i], err[i]);
  }
  EXPECT_LT(err[0], 2e-3 * h_top);
  EXPECT_GT(err[0] / err[1], 4.0);
}

TEST(Cascade, GivenInitialLevelsAndOuterLevel) {
  // the linear cascade from given initial levels (not at rest) against its
  // closed form; an outer level above the trajectory changes nothing, one
  // below it holds h there
  const double al = 0.3, ga = 0.12, b = 0.8, d = 0.05, c = 1.5, ts = 1;
  const long n = 800;
  const std::vector<double> u = staircase(n, 60, 0, 5, 11);
  double z = 9.0, h = 2.0;
  std::vector<double> exact(n);
  double top = -INFINITY;
  for (long k = 0; k < n; ++k) {
    exact[k] = h + c;
    top = std::max(top, h);
    linear_cascade_step(al, ga, b * u[k] + d, ts, z, h);
  }
  CascadeConfig<double> cfg =
      cascade(false, b, d, al, ga, INFINITY, c, ts, 20);
  cfg.z0 = Eigen::VectorXd::Constant(1, 9.0);
  cfg.h0 = Eigen::VectorXd::Constant(1, 2.0);
  std::vector<double> y(n), y2(n), y3(n);
  ASSERT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y.data(), nullptr).ok());
  for (long k = 0; k < n; ++k) ASSERT_NEAR(y[k], exact[k], 1e-6 * top);
  cfg.ho = Eigen::VectorXd::Constant(1, 2 * top);
  ASSERT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y2.data(), nullptr).ok());
  for (long k = 0; k < n; ++k) ASSERT_EQ(y2[k], y[k]);
  const double lid = 0.5 * top;
  cfg.ho(0) = lid;
  ASSERT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y3.data(), nullptr).ok());
  long held = 0;
  for (long k = 0; k < n; ++k) {
    ASSERT_LE(y3[k], lid + c);
    held += y3[k] == lid + c;
  }
  EXPECT_GT(held, 0);
  // one set given, one not: refused
  cfg.z0.resize(0);
  EXPECT_EQ(simulate_cascade<double>(cfg, u.data(), n, y.data(), nullptr)
                .code(),
            ErrorCode::kDimensionMismatch);
}

TEST(Cascade, SpilledShareReachesTheOuterState) {
  // z held at its level by a constant inflow q > alpha hi: the water over
  // the level, (q - alpha hi) per unit time, is lost but for the share s
  // that enters h in h's units (1/alpha), so that h' = hi - gamma h +
  // s (q - alpha hi) / alpha tends to its steady state; the error of the
  // projection is O(sub-step)
  const double al = 0.3, ga = 0.12, q = 3, top = 4, s = 0.6, ts = 1;
  const long n = 400;  // 48 time constants of h
  const std::vector<double> u(n, 1.0);
  const double h_ss = (top + s * (q - al * top) / al) / ga;
  CascadeConfig<double> cfg = cascade(false, q, 0, al, ga, top, 0, ts, 8);
  cfg.spill = Eigen::VectorXd::Constant(1, s);
  std::vector<double> y(n), z(n), y0(n);
  double err[2];
  const int steps[2] = {8, 64};
  for (int i = 0; i < 2; ++i) {
    err[i] = final_error_at_level(cfg, steps[i], u, h_ss, y, z);
  }
  EXPECT_LT(err[1], 1e-2 * h_ss);
  EXPECT_GT(err[0] / err[1], 4.0);
  // a share of 0 is no spill at all
  cfg.spill(0) = 0;
  ASSERT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y.data(), nullptr).ok());
  cfg.spill.resize(0);
  ASSERT_TRUE(
      simulate_cascade<double>(cfg, u.data(), n, y0.data(), nullptr).ok());
  for (long k = 0; k < n; ++k) ASSERT_EQ(y[k], y0[k]);
  cfg.spill = Eigen::VectorXd::Constant(1, 1.5);
  EXPECT_EQ(simulate_cascade<double>(cfg, u.data(), n, y.data(), nullptr)
                .code(),
            ErrorCode::kBadInput);
}

TEST(Cascade, SideBySideEqualsAlone) {
  const long n = 500;
  const std::vector<double> u = staircase(2 * n, 40, 2, 7, 3);  // 2 channels
  CascadeConfig<double> all;
  all.sqrt_nodes = true;
  all.b.resize(2, 3);
  all.b << 0.0012, 0.001, 0.0015, 0.0003, -0.0002, 0.0;
  all.d = Eigen::Vector3d(0.001, 0.0, 0.002);
  all.alpha = Eigen::Vector3d(0.01, 0.011, 0.009);
  all.gamma = Eigen::Vector3d(0.085, 0.08, 0.09);
  all.hi = Eigen::Vector3d(0.3, 0.25, INFINITY);
  all.c = Eigen::Vector3d(0.0, 1.0, -1.0);
  all.ts = 2;
  all.substeps = 4;
  std::vector<double> y(3 * n), z(3 * n);
  ASSERT_TRUE(
      simulate_cascade<double>(all, u.data(), n, y.data(), z.data()).ok());
  for (int i = 0; i < 3; ++i) {
    CascadeConfig<double> one = all;
    one.b = all.b.col(i);
    one.d = all.d.segment(i, 1);
    one.alpha = all.alpha.segment(i, 1);
    one.gamma = all.gamma.segment(i, 1);
    one.hi = all.hi.segment(i, 1);
    one.c = all.c.segment(i, 1);
    std::vector<double> yi(n), zi(n);
    ASSERT_TRUE(
        simulate_cascade<double>(one, u.data(), n, yi.data(), zi.data()).ok());
    for (long k = 0; k < n; ++k) {
      ASSERT_EQ(y[k + i * n], yi[k]);
      ASSERT_EQ(z[k + i * n], zi[k]);
    }
  }
}

// Far from its levels the end stop is the linear model: its exact ZOH
// response by partial fractions, F with distinct real poles -p_i, B(s) of
// relative degree two; each mode m_i' = -p_i m_i + u stepped exactly.
void check_linear_stop(const std::vector<double>& poles,
                       const std::vector<double>& num) {
  const int n = static_cast<int>(poles.size());
  Eigen::VectorXd F = Eigen::VectorXd::Ones(1);
  for (double p : poles) {
    Eigen::VectorXd G = Eigen::VectorXd::Zero(F.size() + 1);
    G.head(F.size()) += F;
    G.tail(F.size()) += p * F;
    F = G;
  }
  EndStopConfig<double> cfg;
  cfg.f = F.tail(n);
  cfg.b = Eigen::MatrixXd::Zero(n, 1);
  for (std::size_t i = 0; i < num.size(); ++i) {
    cfg.b(n - num.size() + i, 0) = num[i];
  }
  cfg.ts = 0.01;
  cfg.substeps = 20;
  cfg.lo = -1e6;
  cfg.hi = 1e6;
  const long len = 3000;
  const std::vector<double> u = staircase(len, 100, -5, 5, 11);
  std::vector<double> x(len);
  ASSERT_TRUE(simulate_end_stop<double>(cfg, u.data(), len, x.data()).ok());
  std::vector<double> res(n), m(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const double s = -poles[i];
    double nv = 0;
    for (double c : num) nv = nv * s + c;
    double den = 1;
    for (int j = 0; j < n; ++j) {
      if (j != i) den *= (s + poles[j]);
    }
    res[i] = nv / den;
  }
  double err = 0, range = 0;
  for (long k = 0; k < len; ++k) {
    double y = 0;
    for (int i = 0; i < n; ++i) y += res[i] * m[i];
    err = std::max(err, std::abs(x[k] - y));
    range = std::max(range, std::abs(y));
    for (int i = 0; i < n; ++i) {
      const double e = std::exp(-poles[i] * cfg.ts);
      m[i] = e * m[i] + (1 - e) / poles[i] * u[k];
    }
  }
  EXPECT_GT(range, 0.1);
  EXPECT_LT(err, 1e-10 * range);
}

TEST(EndStop, FarFromLevelsIsLinearZoh) {
  check_linear_stop({3.0, 8.0}, {50.0});
  check_linear_stop({2.0, 5.0, 9.0}, {4.0, 30.0});
}

// x'' = u (F = p^2): from rest with u = 1 the position is t^2/2 until the
// sub-step that crosses hi, where it stops with the velocity zero; it stays
// while u pushes into the stop and leaves as hi - t^2/2 when u reverses.
TEST(EndStop, DoubleIntegratorHitsAndLeaves) {
  EndStopConfig<double> cfg;
  cfg.f = Eigen::Vector2d(0, 0);
  cfg.b = Eigen::MatrixXd::Zero(2, 1);
  cfg.b(1, 0) = 1;
  cfg.ts = 1;
  cfg.substeps = 10;
  cfg.hi = 2.0;  // t^2/2 = 2 at t = 2: crossed in the sub-step [2, 2.1]
  cfg.lo = -100;
  const long n = 12;
  std::vector<double> u(n, 1.0);
  for (long k = 6; k < n; ++k) u[k] = -1.0;
  std::vector<double> x(n);
  ASSERT_TRUE(simulate_end_stop<double>(cfg, u.data(), n, x.data()).ok());
  EXPECT_NEAR(x[0], 0.0, 1e-14);
  EXPECT_NEAR(x[1], 0.5, 1e-12);
  EXPECT_NEAR(x[2], 2.0, 1e-12);  // exactly at the level at t = 2
  for (long k = 3; k <= 6; ++k) EXPECT_EQ(x[k], 2.0);
  for (long k = 7; k < n; ++k) {
    const double t = static_cast<double>(k - 6);
    EXPECT_NEAR(x[k], 2.0 - t * t / 2, 1e-12) << "k = " << k;
  }
}

TEST(EndStop, NeverLeavesItsLevelsAndBadInput) {
  EndStopConfig<double> cfg;
  cfg.f = Eigen::Vector3d(2.0, 10.0, 8.0);
  cfg.b = Eigen::MatrixXd::Zero(3, 1);
  cfg.b(2, 0) = 200;
  cfg.ts = 0.01;
  cfg.substeps = 20;
  cfg.lo = -3;
  cfg.hi = 4;
  const long n = 4000;
  const std::vector<double> u = staircase(n, 150, -1, 1, 5);
  std::vector<double> x(n);
  ASSERT_TRUE(simulate_end_stop<double>(cfg, u.data(), n, x.data()).ok());
  long at = 0;
  for (long k = 0; k < n; ++k) {
    ASSERT_GE(x[k], cfg.lo);
    ASSERT_LE(x[k], cfg.hi);
    at += (x[k] == cfg.lo || x[k] == cfg.hi);
  }
  EXPECT_GT(at, n / 20);  // the stops are reached
  EndStopConfig<double> bad = cfg;
  bad.b(0, 0) = 1;  // relative degree one: no velocity state
  EXPECT_EQ(simulate_end_stop<double>(bad, u.data(), n, x.data()).code(),
            ErrorCode::kBadInput);
  bad = cfg;
  bad.f = Eigen::VectorXd::Ones(1);
  bad.b = Eigen::MatrixXd::Zero(1, 1);
  EXPECT_EQ(simulate_end_stop<double>(bad, u.data(), n, x.data()).code(),
            ErrorCode::kBadInput);
  bad = cfg;
  bad.b = Eigen::MatrixXd::Zero(2, 1);
  EXPECT_EQ(simulate_end_stop<double>(bad, u.data(), n, x.data()).code(),
            ErrorCode::kDimensionMismatch);
  CascadeConfig<double> c = cascade(true, 1, 0, 1, 1, INFINITY, 0, 1, 1);
  c.alpha = Eigen::VectorXd::Ones(2);
  EXPECT_EQ(simulate_cascade<double>(c, u.data(), n, x.data(), nullptr).code(),
            ErrorCode::kDimensionMismatch);
}

}  // namespace
}  // namespace ctid
