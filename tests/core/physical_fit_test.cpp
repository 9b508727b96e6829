// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/physical_fit.hpp against
// simulators written here, apart from the core's:
//   - an end stop (a mass on a spring, x'' = -f1 x' - f2 x + b u, in its
//     physical coordinates, each sub-step exact by the matrix exponential,
//     the velocity reset at a level) and a square-root cascade with an
//     overflowing inner tank (Runge-Kutta written out): the fit started
//     10 % off recovers their known parameters from noise-free records;
//   - the Gauss-Newton covariance of a cascade fitted on a noisy record
//     against s^2 (J^T J)^-1 with J by central differences of the test's
//     simulator at the estimate;
//   - the simulations of simulate_physical against the test's simulators,
//     several models side by side (with and without initial levels) equal
//     to each alone, and a declared initial state's free response removed
//     exactly;
//   - a cascade started from a linear model: its linearisation has the
//     model's poles, its steady state the level and gain asked for;
//   - bad input.
#include "ctid/apps/residtrace/physical_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

namespace ctid::residtrace {
namespace {

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

// The end stop in the coordinates (position, velocity): a whole interval
// exact; where it ends beyond a level, the interval again in sub-steps,
// the first one beyond it ending at the level at rest; held while the
// acceleration -f2 L + b u points into the stop (tested at each sample).
std::vector<double> end_stop(double f1, double f2, double b, double lo,
                             double hi, double c, double ts, int substeps,
                             const std::vector<double>& u) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  A(0, 1) = 1;
  A(1, 0) = -f2;
  A(1, 1) = -f1;
  A(1, 2) = b;  // the input held, as a third state
  const Eigen::Matrix3d Ed = (A * ts).exp();
  const Eigen::Matrix3d Es = (A * (ts / substeps)).exp();
  double x = 0, v = 0;
  int held = 0;
  std::vector<double> y(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) {
    y[k] = x + c;
    if (held != 0) {
      const double acc = -f2 * x + b * u[k];
      if ((held > 0 && acc >= 0) || (held < 0 && acc <= 0)) continue;
      held = 0;
    }
    Eigen::Vector3d s(x, v, u[k]);
    const Eigen::Vector3d whole = Ed * s;
    if (whole(0) >= lo && whole(0) <= hi) {
      x = whole(0);
      v = whole(1);
      continue;
    }
    for (int i = 0; i < substeps && held == 0; ++i) {
      s = Es * s;
      if (s(0) > hi || s(0) < lo) {
        held = s(0) > hi ? 1 : -1;
        s(0) = held > 0 ? hi : lo;
        s(1) = 0;
      }
    }
    x = s(0);
    v = s(1);
  }
  return y;
}

struct Tanks {
  double b, d, alpha, gamma, c, top, h0;
};

// z' = b u + d - alpha sqrt(z) (z in [0, top], the water above lost),
// h' = sqrt(z) - gamma sqrt(h), y = c + h; classical Runge-Kutta in
// `substeps` sub-steps, from h0 and the inner level at rest with it.
std::vector<double> tanks(const Tanks& p, double ts, int substeps,
                          const std::vector<double>& u) {
  auto g = [](double s) { return std::sqrt(std::max(s, 0.0)); };
  double h = p.h0;
  double z = std::min(p.gamma * p.gamma * h, p.top);
  const double dt = ts / substeps;
  std::vector<double> y(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) {
    y[k] = p.c + h;
    const double q = p.b * u[k] + p.d;
    auto fz = [&](double zz) { return q - p.alpha * g(zz); };
    auto fh = [&](double zz, double hh) { return g(zz) - p.gamma * g(hh); };
    for (int i = 0; i < substeps; ++i) {
      const double k1z = fz(z), k1h = fh(z, h);
      const double k2z = fz(z + dt / 2 * k1z),
                   k2h = fh(z + dt / 2 * k1z, h + dt / 2 * k1h);
      const double k3z = fz(z + dt / 2 * k2z),
                   k3h = fh(z + dt / 2 * k2z, h + dt / 2 * k2h);
      const double k4z = fz(z + dt * k3z), k4h = fh(z + dt * k3z, h + dt * k3h);
      z = std::min(std::max(z + dt / 6 * (k1z + 2 * k2z + 2 * k3z + k4z), 0.0),
                   p.top);
      h = std::max(h + dt / 6 * (k1h + 2 * k2h + 2 * k3h + k4h), 0.0);
    }
  }
  return y;
}

PhysicalModel<double> stop_model(double f1, double f2, double b, double lo,
                                 double hi, double c, int substeps) {
  PhysicalModel<double> m;
  m.kind = PhysicalKind::kStop;
  m.F = Eigen::Vector3d(1, f1, f2);
  m.fixed = {false, false};
  m.B = {Eigen::VectorXd::Constant(1, b)};
  m.has_offset = true;
  m.offset = c;
  m.lo = lo;
  m.hi = hi;
  m.substeps = substeps;
  m.yscale = 10;
  return m;
}

PhysicalModel<double> tanks_model(const Tanks& p, int substeps, double wbar) {
  PhysicalModel<double> m;
  m.kind = PhysicalKind::kCascade;
  m.sqrt_nodes = true;
  m.b = Eigen::VectorXd::Constant(1, p.b);
  m.d = p.d;
  m.alpha = p.alpha;
  m.gamma = p.gamma;
  m.c = p.c;
  m.hi = p.top;
  m.has_h0 = true;
  m.h0 = p.h0;
  m.wbar = Eigen::VectorXd::Constant(1, wbar);
  m.substeps = substeps;
  m.yscale = 5;
  return m;
}

Eigen::VectorXd tanks_theta(const Tanks& p) {
  Eigen::VectorXd th(7);
  th << p.b, p.d, std::log(p.alpha), std::log(p.gamma), p.c, p.top, p.h0;
  return th;
}

Tanks tanks_of(const Eigen::VectorXd& th) {
  return {th(0), th(1), std::exp(th(2)), std::exp(th(3)), th(4), th(5), th(6)};
}

const Tanks kTanks{0.05, 0.02, 0.1, 0.5, 1.0, 3.0, 4.0};

TEST(PhysicalSimulation, MatchesTheTestSimulators) {
  const double ts = 0.02;
  const std::vector<double> u = staircase(1500, 40, -2, 2, 3);
  // levels in output units: lo - c = -3.5, hi - c = 4.5 of the position
  const std::vector<double> y = end_stop(4, 49, 300, -3.5, 4.5, 1.5, ts, 10, u);
  Eigen::MatrixXd Y, Z;
  ASSERT_TRUE(
      simulate_physical<double>({stop_model(4, 49, 300, -2, 6, 1.5, 10)},
                                u.data(), 1500, 1, ts, &Y, &Z)
          .ok());
  double worst = 0;
  long held = 0;
  for (long k = 0; k < 1500; ++k) {
    worst = std::max(worst, std::abs(Y(k, 0) - y[k]));
    if (y[k] == 6 || y[k] == -2) ++held;
  }
  EXPECT_LT(worst, 1e-9 * 8);
  EXPECT_GT(held, 100);  // both stops are reached

  const std::vector<double> w = staircase(800, 25, 0, 4, 5);
  const std::vector<double> yt = tanks(kTanks, 2.0, 5, w);
  ASSERT_TRUE(simulate_physical<double>({tanks_model(kTanks, 5, 2.0)}, w.data(),
                                        800, 1, 2.0, &Y, &Z)
                  .ok());
  double worst_t = 0;
  for (long k = 0; k < 800; ++k) {
    worst_t = std::max(worst_t, std::abs(Y(k, 0) - yt[k]));
  }
  EXPECT_LT(worst_t, 1e-10);
  EXPECT_GT((Z.col(0).array() >= kTanks.top).count(), 20);  // it overflows
}

TEST(PhysicalSimulation, SideBySideEqualsAlone) {
  // cascades with and without initial levels (simulated in separate
  // passes), one with an outer level and a spilled share
  const std::vector<double> w = staircase(600, 25, 0, 4, 9);
  PhysicalModel<double> a = tanks_model(kTanks, 5, 2.0);
  PhysicalModel<double> b = a;
  b.has_h0 = false;
  PhysicalModel<double> c = a;
  c.alpha = 0.12;
  c.has_yhi = true;
  c.yhi = 12;
  c.has_spill = true;
  c.spill = 0.3;
  Eigen::MatrixXd Y, Z, Y1, Z1;
  ASSERT_TRUE(
      simulate_physical<double>({b, a, c}, w.data(), 600, 1, 2.0, &Y, &Z).ok());
  const std::vector<PhysicalModel<double>> alone = {b, a, c};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(
        simulate_physical<double>({alone[i]}, w.data(), 600, 1, 2.0, &Y1, &Z1)
            .ok());
    EXPECT_EQ((Y.col(i) - Y1.col(0)).cwiseAbs().maxCoeff(), 0) << i;
    EXPECT_EQ((Z.col(i) - Z1.col(0)).cwiseAbs().maxCoeff(), 0) << i;
  }
  EXPECT_GT((Y.col(1) - Y.col(0)).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT((Y.col(2) - Y.col(1)).cwiseAbs().maxCoeff(), 1e-3);
}

TEST(PhysicalStart, CascadeFromItsLinearisation) {
  // the cascade's linearisation has the poles and gain asked for, and
  // its steady state for the mean inflow is at the level asked for: the
  // test simulator run to rest with the input at wbar, and at wbar +- 0.05
  // for the gain (a central secant)
  for (const bool sq : {true, false}) {
    PhysicalModel<double> m;
    m.kind = PhysicalKind::kCascade;
    m.sqrt_nodes = sq;
    cascade_from_linear<double>(0.05, 0.01, Eigen::VectorXd::Constant(1, 3.0),
                                Eigen::VectorXd::Constant(1, 2.0), 8.0, &m);
    const Eigen::VectorXd F = cascade_linearisation(m);
    EXPECT_NEAR(F(1), 0.06, 1e-15);
    EXPECT_NEAR(F(2), 0.0005, 1e-16);
    EXPECT_EQ(m.F, F);
    if (!sq) {
      // linear: the static gain b / (alpha gamma) and the level exactly
      EXPECT_NEAR(m.b(0) / (m.alpha * m.gamma), 3.0, 1e-12);
      EXPECT_NEAR((2.0 * m.b(0) + m.d) / (m.alpha * m.gamma), 8.0, 1e-12);
      continue;
    }
    const Tanks p{m.b(0), m.d, m.alpha, m.gamma, 0.0, 1e9, 8.0};
    const std::vector<double> at(3000, 2.0), above(3000, 2.05),
        below(3000, 1.95);
    const double h_at = tanks(p, 1.0, 2, at).back();
    const double h_above = tanks(p, 1.0, 2, above).back();
    const double h_below = tanks(p, 1.0, 2, below).back();
    EXPECT_NEAR(h_at, 8.0, 1e-9);
    EXPECT_NEAR((h_above - h_below) / 0.1, 3.0, 1e-3);
  }
}

TEST(PhysicalFit, RecoversAnEndStop) {
  const double ts = 0.02;
  const std::vector<double> u = staircase(1500, 40, -2, 2, 3);
  const std::vector<double> y = end_stop(4, 49, 300, -3.5, 4.5, 1.5, ts, 10, u);
  const Eigen::Map<const Eigen::VectorXd> yv(y.data(), 1500);
  // 10 % off
  const PhysicalModel<double> start =
      stop_model(4.4, 44, 330, -2.2, 5.4, 1.35, 10);
  PhysicalFit<double> fit;
  ASSERT_TRUE(
      fit_physical<double>(start, u.data(), 1, yv, ts, false, 30, &fit).ok());
  ASSERT_TRUE(fit.ok);
  Eigen::VectorXd truth(6);
  truth << 4, 49, 300, 1.5, -2, 6;
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(fit.theta(i), truth(i), 1e-5 * std::abs(truth(i))) << i;
  }
  EXPECT_NEAR(fit.model.lo, -2, 1e-5);
  EXPECT_NEAR(fit.model.hi, 6, 1e-5);
  EXPECT_LT(fit.e.norm(), 1e-6 * yv.norm());
}

TEST(PhysicalFit, RecoversACascade) {
  const double ts = 2;
  const std::vector<double> w = staircase(800, 25, 0, 4, 5);
  const std::vector<double> y = tanks(kTanks, ts, 5, w);
  const Eigen::Map<const Eigen::VectorXd> yv(y.data(), 800);
  const Eigen::VectorXd truth = tanks_theta(kTanks);
  Eigen::VectorXd th0 = truth;
  th0(0) *= 1.1;
  th0(1) *= 0.9;
  th0(2) += 0.1;
  th0(3) -= 0.1;
  th0(4) *= 1.1;
  th0(5) *= 0.9;
  th0(6) *= 1.1;
  PhysicalFit<double> fit;
  ASSERT_TRUE(fit_physical<double>(tanks_model(tanks_of(th0), 5, 2.0), w.data(),
                                   1, yv, ts, false, 30, &fit)
                  .ok());
  ASSERT_TRUE(fit.ok);
  ASSERT_EQ(fit.theta.size(), 7);
  for (int i = 0; i < 7; ++i) {
    EXPECT_NEAR(fit.theta(i), truth(i),
                1e-4 * std::max(1.0, std::abs(truth(i))))
        << i;
  }
  EXPECT_LT(fit.e.norm(), 1e-6 * yv.norm());
  // the linear part: the cascade's linearisation
  const double q = 2.0 * fit.model.b(0) + fit.model.d;
  const double p1 = fit.model.alpha * fit.model.alpha / (2 * q);
  const double p2 =
      fit.model.alpha * fit.model.gamma * fit.model.gamma / (2 * q);
  EXPECT_NEAR(fit.model.F(1), p1 + p2, 1e-12);
  EXPECT_NEAR(fit.model.F(2), p1 * p2, 1e-12);
}

TEST(PhysicalFit, CovarianceIsTheGaussNewtonOne) {
  const double ts = 2;
  const long N = 800;
  const std::vector<double> w = staircase(N, 25, 0, 4, 5);
  std::vector<double> y = tanks(kTanks, ts, 5, w);
  std::mt19937 gen(17);
  std::normal_distribution<double> noise(0, 0.05);
  for (double& v : y) v += noise(gen);
  const Eigen::Map<const Eigen::VectorXd> yv(y.data(), N);
  PhysicalFit<double> fit;
  ASSERT_TRUE(fit_physical<double>(tanks_model(kTanks, 5, 2.0), w.data(), 1, yv,
                                   ts, false, 30, &fit)
                  .ok());
  ASSERT_TRUE(fit.ok);
  const Eigen::VectorXd th = fit.theta;
  const int np = 7;
  Eigen::MatrixXd J(N, np);
  for (int i = 0; i < np; ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(th(i)));
    Eigen::VectorXd tp = th, tm = th;
    tp(i) += h;
    tm(i) -= h;
    const std::vector<double> yp = tanks(tanks_of(tp), ts, 5, w);
    const std::vector<double> ym = tanks(tanks_of(tm), ts, 5, w);
    for (long k = 0; k < N; ++k) J(k, i) = (yp[k] - ym[k]) / (2 * h);
  }
  const std::vector<double> yh = tanks(tanks_of(th), ts, 5, w);
  double sse = 0;
  for (long k = 0; k < N; ++k) sse += (y[k] - yh[k]) * (y[k] - yh[k]);
  EXPECT_NEAR(sse, fit.sse, 1e-9 * sse);
  const Eigen::MatrixXd C = sse / (N - np) * (J.transpose() * J).inverse();
  for (int i = 0; i < np; ++i) {
    EXPECT_NEAR(fit.cov(i, i), C(i, i), 1e-3 * C(i, i)) << i;
    for (int j = 0; j < i; ++j) {
      EXPECT_NEAR(fit.cov(i, j), C(i, j), 1e-3 * std::sqrt(C(i, i) * C(j, j)))
          << i << "," << j;
    }
  }
  // the residual variance and BIC of the whole record
  EXPECT_NEAR(fit.s2, sse / (N - np), 1e-9 * fit.s2);
  EXPECT_NEAR(fit.bic, N * std::log(fit.s2) + np * std::log(double(N)), 1e-9);
}

TEST(PhysicalFit, DeclaredInitialStateRemovesTheFreeResponse) {
  // an end stop whose levels are never reached: the linear model; the
  // record carries a free response of F on top, which the fit removes
  const double ts = 0.02;
  const long N = 1000;
  const std::vector<double> u = staircase(N, 40, -1, 1, 8);
  std::vector<double> y = end_stop(4, 49, 30, -1e3, 1e3, 0, ts, 1, u);
  // free response of p^2 + 4p + 49 from x(0) = 0.7, x'(0) = 0:
  // poles -2 +- j sqrt(45)
  const double wd = std::sqrt(45.0);
  for (long k = 0; k < N; ++k) {
    const double t = k * ts;
    y[k] +=
        0.7 * std::exp(-2 * t) * (std::cos(wd * t) + 2 / wd * std::sin(wd * t));
  }
  const Eigen::Map<const Eigen::VectorXd> yv(y.data(), N);
  PhysicalModel<double> m = stop_model(4, 49, 30, -1e3, 1e3, 0, 1);
  m.has_offset = false;
  Eigen::MatrixXd E;
  physical_detail::errors<double>({m}, u.data(), 1, Eigen::VectorXd(yv), ts,
                                  true, &E);
  EXPECT_LT(E.col(0).norm(), 1e-8 * yv.norm());
  physical_detail::errors<double>({m}, u.data(), 1, Eigen::VectorXd(yv), ts,
                                  false, &E);
  EXPECT_GT(E.col(0).norm(), 0.1);
}

TEST(PhysicalFit, BadInput) {
  PhysicalFit<double> fit;
  const std::vector<double> u(10, 1.0);
  const Eigen::VectorXd y = Eigen::VectorXd::Ones(10);
  PhysicalModel<double> m = stop_model(4, 49, 30, -1, 1, 0, 1);
  m.F = Eigen::Vector2d(1, 2);  // first order
  EXPECT_EQ(fit_physical<double>(m, u.data(), 1, y, 0.1, false, 5, &fit).code(),
            ErrorCode::kBadInput);
  m = stop_model(4, 49, 30, -1, 1, 0, 1);
  EXPECT_EQ(fit_physical<double>(m, u.data(), 1, y, 0.0, false, 5, &fit).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(fit_physical<double>(m, u.data(), 1, Eigen::VectorXd(), 0.1, false,
                                 5, &fit)
                .code(),
            ErrorCode::kBadInput);
  // a record the model cannot simulate to a finite error: not ok, no error
  Eigen::VectorXd yn = y;
  yn(3) = NAN;
  ASSERT_TRUE(
      fit_physical<double>(m, u.data(), 1, yn, 0.1, false, 5, &fit).ok());
  EXPECT_FALSE(fit.ok);
}

}  // namespace
}  // namespace ctid::residtrace
