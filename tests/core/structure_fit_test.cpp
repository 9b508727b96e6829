// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/structure_fit.hpp:
//   - the channel signals against their definitions computed here, the
//     node channel against the exact ZOH response of Fa(0)/Fa(p) by the
//     matrix exponential (test_util.hpp), clipped;
//   - recovery of a known structure simulated here (exact ZOH, noise
//     free): a second-order model with two channels, the record's level
//     estimated jointly, an integrator fixed in F;
//   - the output terms of the alternation against a direct least squares
//     on y minus the fitted model's output simulated here, and against
//     the values that generated them;
//   - the censored fit of an output saturation whose levels are known,
//     against the structure that generated the clipped record, and the
//     bias of the same fit without the saturation;
//   - missing samples carry no error and do not move the estimate;
//   - bad structures are identified errors.
#include "ctid/apps/residtrace/structure_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

using Channel = StructureChannel<double>;

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double a : v) x(i++) = a;
  return x;
}

Eigen::VectorXd zoh(const Eigen::VectorXd& num, const Eigen::VectorXd& den,
                    const Eigen::VectorXd& v, double ts) {
  const std::vector<double> s(v.data(), v.data() + v.size());
  const std::vector<double> y = test::simulate_zoh(num, den, s, ts);
  return Eigen::Map<const Eigen::VectorXd>(y.data(), y.size());
}

Channel channel(ChannelKind kind, int col, double param, int nb) {
  Channel c;
  c.kind = kind;
  c.col = col;
  c.param = param;
  c.nb = nb;
  c.B = Eigen::VectorXd::Zero(nb);
  return c;
}

// A multilevel input held 8 samples (rich enough for two channels).
Eigen::VectorXd held_input(int N, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  Eigen::VectorXd u(N);
  double level = 0;
  for (int k = 0; k < N; ++k) {
    if (k % 8 == 0) level = d(rng);
    u(k) = level;
  }
  return u;
}

TEST(StructureFit, ChannelSignalsFollowTheirDefinitions) {
  const int N = 6;
  Eigen::MatrixXd u(N, 2);
  u << 1, -2, 3, 0.5, -2, 1, 5, -1, 0, 2, -4, 0;
  Eigen::MatrixXd v(N, 2);
  v << 1, -1, -2, 0, 0, 3, 4, -5, -1, 2, 0, -1;
  const Eigen::VectorXd y = vec({-8, 4, 0, 2.25, -1, 1});
  std::vector<Channel> ch = {channel(ChannelKind::kInput, 0, 0.25, 1),
                             channel(ChannelKind::kConstant, -1, 0, 1),
                             channel(ChannelKind::kSignV, -1, 0, 1),
                             channel(ChannelKind::kSignOutput, -1, 0, 1),
                             channel(ChannelKind::kPower, 1, 3, 1),
                             channel(ChannelKind::kClip, 0, 2.5, 1),
                             channel(ChannelKind::kOutputPower, -1, 0.5, 1),
                             channel(ChannelKind::kOutputPower, -1, 2, 1)};
  Eigen::MatrixXd W;
  ASSERT_TRUE(channel_signals<double>(ch, u, v, y, &W).ok());
  ASSERT_EQ(W.cols(), 8);
  for (int k = 0; k < N; ++k) {
    const double prev = u(k > 0 ? k - 1 : 0, 0);
    EXPECT_DOUBLE_EQ(W(k, 0), 0.75 * u(k, 0) + 0.25 * prev);
    EXPECT_EQ(W(k, 1), 1);
    EXPECT_EQ(W(k, 2), (v(k, 0) > 0) - (v(k, 0) < 0));
    EXPECT_EQ(W(k, 3), (v(k, 1) > 0) - (v(k, 1) < 0));
    EXPECT_DOUBLE_EQ(W(k, 4), u(k, 1) * u(k, 1) * u(k, 1));
    EXPECT_EQ(W(k, 5), std::min(std::max(u(k, 0), -2.5), 2.5));
    const double s = (y(k) > 0) - (y(k) < 0);
    EXPECT_DOUBLE_EQ(W(k, 6), s * std::sqrt(std::abs(y(k))));
    EXPECT_DOUBLE_EQ(W(k, 7), y(k) * y(k));
  }
  // the fraction of a sample leaves a whole-sample input as it is
  ch[0].param = 0;
  ASSERT_TRUE(channel_signals<double>(ch, u, v, y, &W).ok());
  EXPECT_TRUE(test::MatrixNear(W.col(0), u.col(0), 0));
}

TEST(StructureFit, NodeChannelIsTheClippedUnitGainLag) {
  const int N = 200;
  const double ts = 0.1;
  Eigen::MatrixXd u(N, 1);
  u.col(0) = 2 * held_input(N, 3);
  Channel c = channel(ChannelKind::kNode, 0, 0, 1);
  c.node_f = vec({2, 1.2});  // 0.6 / (p + 0.6)
  c.node_ts = ts;
  c.node_lo = -0.5;
  c.node_hi = 0.8;
  Eigen::MatrixXd W;
  ASSERT_TRUE(
      channel_signals<double>({c}, u, Eigen::MatrixXd(), Eigen::VectorXd(), &W)
          .ok());
  const Eigen::VectorXd z = zoh(vec({1.2}), vec({2, 1.2}), u.col(0), ts);
  const Eigen::VectorXd clipped = z.cwiseMax(-0.5).cwiseMin(0.8);
  EXPECT_TRUE(test::MatrixNear(W.col(0), clipped, 1e-10));
  EXPECT_GT(z.maxCoeff(), 0.9);  // the levels are reached
  EXPECT_LT(z.minCoeff(), -0.6);
}

// y = 5 + (p + 2) / (p^2 + 3p + 2.5) u1 + 0.4 / (..) u2^2 from rest.
struct Known {
  Eigen::VectorXd F = vec({1, 3, 2.5});
  Eigen::VectorXd B1 = vec({1, 2});
  Eigen::VectorXd B2 = vec({0.4});
  double level = 5;
  double ts = 0.05;
  Eigen::MatrixXd u;
  Eigen::VectorXd x;

  explicit Known(int N) {
    u.resize(N, 2);
    u.col(0) = held_input(N, 11);
    u.col(1) = held_input(N, 12);
    x = zoh(B1, F, u.col(0), ts) +
        zoh(B2, F, u.col(1).array().square().matrix(), ts);
  }

  StructureModel<double> model(bool levels) const {
    StructureModel<double> m;
    m.F = vec({1, 0, 0});
    m.fixed = {false, false};
    // started from rough numerators (a start of zeros gives the engine
    // no instruments)
    m.channels = {channel(ChannelKind::kInput, 0, 0, 2),
                  channel(ChannelKind::kPower, 1, 2, 1)};
    m.channels[0].B = vec({0.5, 1});
    m.channels[1].B = vec({0.2});
    if (levels) {
      OutputTerm<double> t;
      t.kind = OutputTermKind::kOffset;
      t.c = vec({0});
      m.out.push_back(t);
      m.levels = true;
    }
    return m;
  }
};

TEST(StructureFit, RecoversAKnownStructureAndItsLevel) {
  const int N = 1500;
  Known k(N);
  StructureRecord<double> rec;
  rec.y = k.x.array() + k.level;
  rec.u = k.u;
  rec.ts = k.ts;
  StructureFit<double> fit;
  const std::vector<Eigen::VectorXd> starts = {vec({1, 2, 1})};
  ASSERT_TRUE(fit_structure<double>(k.model(true), rec, starts, 30, &fit).ok());
  ASSERT_TRUE(fit.ok);
  EXPECT_TRUE(test::MatrixNear(fit.F, k.F, 1e-6));
  EXPECT_TRUE(test::MatrixNear(fit.B[0], k.B1, 1e-6));
  EXPECT_TRUE(test::MatrixNear(fit.B[1], k.B2, 1e-6));
  ASSERT_EQ(fit.out.size(), 1u);
  EXPECT_TRUE(fit.out[0].fitted);
  EXPECT_NEAR(fit.out[0].c(0), k.level, 1e-6);
  // theta = [f1 f2 b1 b2 b3]; np adds the level
  EXPECT_EQ(fit.theta.size(), 5);
  EXPECT_EQ(fit.np, 6);
  EXPECT_LT(std::sqrt(fit.s2), 1e-6);
  EXPECT_NEAR(fit.bic, N * std::log(fit.s2) + 6 * std::log(double(N)), 1e-9);
  // the engine's automatic start finds it too
  ASSERT_TRUE(
      fit_structure<double>(k.model(true), rec, {Eigen::VectorXd()}, 30, &fit)
          .ok());
  ASSERT_TRUE(fit.ok);
  EXPECT_TRUE(test::MatrixNear(fit.F, k.F, 1e-6));
}

TEST(StructureFit, KeepsAFixedIntegrator) {
  // y = (p + 0.5) / (p (p + 2)) u from rest: F's last coefficient stays
  // fixed at exactly 0, the others are recovered
  const int N = 1200;
  const double ts = 0.05;
  const Eigen::VectorXd u =
      held_input(N, 21) - Eigen::VectorXd::Constant(N, 0.02);
  StructureRecord<double> rec;
  rec.u = u;
  rec.ts = ts;
  rec.y = zoh(vec({1, 0.5}), vec({1, 2, 0}), u, ts);
  StructureModel<double> m;
  m.F = vec({1, 0, 0});
  m.fixed = {false, true};
  m.channels = {channel(ChannelKind::kInput, 0, 0, 2)};
  m.channels[0].B = vec({0.5, 1});
  StructureFit<double> fit;
  ASSERT_TRUE(fit_structure<double>(m, rec, {vec({1, 1, 0})}, 30, &fit).ok());
  ASSERT_TRUE(fit.ok);
  EXPECT_TRUE(test::MatrixNear(fit.F, vec({1, 2, 0}), 1e-6));
  EXPECT_EQ(fit.F(2), 0);  // exactly
  EXPECT_TRUE(test::MatrixNear(fit.B[0], vec({1, 0.5}), 1e-6));
  EXPECT_EQ(fit.theta.size(), 3);
  EXPECT_LT(fit.e.cwiseAbs().maxCoeff(), 1e-6);
}

TEST(StructureFit, OutputTermsAreTheLeastSquaresOnTheModelError) {
  // y = x + 0.3 sin(w t) - 0.2 cos(w t) + 0.1 x^2 + 0.05 x^3 + noise:
  // the terms must be the least-squares fit of y minus the fitted model's
  // output (simulated here from the fitted F and B)
  const int N = 2000;
  Known k(N);
  const double w = 7.3;
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0, 0.01);
  Eigen::VectorXd t(N), noise(N);
  for (int i = 0; i < N; ++i) {
    t(i) = i * k.ts;
    noise(i) = g(rng);
  }
  const Eigen::ArrayXd xa = k.x.array();
  StructureRecord<double> rec;
  rec.u = k.u;
  rec.ts = k.ts;
  rec.y = (k.x.array() + 0.3 * (w * t.array()).sin() -
           0.2 * (w * t.array()).cos() + 0.1 * xa.square() + 0.05 * xa.cube())
              .matrix() +
          noise;
  StructureModel<double> m = k.model(false);
  OutputTerm<double> s;
  s.kind = OutputTermKind::kSinusoid;
  s.omega = w;
  s.c = vec({0, 0});
  OutputTerm<double> p;
  p.kind = OutputTermKind::kPolynomial;
  p.c = vec({0, 0});
  m.out = {s, p};
  StructureFit<double> fit;
  ASSERT_TRUE(fit_structure<double>(m, rec, {vec({1, 2, 1})}, 30, &fit).ok());
  ASSERT_TRUE(fit.ok);
  const Eigen::VectorXd xf =
      zoh(fit.B[0], fit.F, k.u.col(0), k.ts) +
      zoh(fit.B[1], fit.F, k.u.col(1).array().square().matrix(), k.ts);
  Eigen::MatrixXd X(N, 4);
  X.col(0) = (w * t.array()).sin();
  X.col(1) = (w * t.array()).cos();
  X.col(2) = xf.array().square();
  X.col(3) = xf.array().cube();
  const Eigen::VectorXd c = X.householderQr().solve(rec.y - xf);
  EXPECT_TRUE(test::MatrixNear(fit.out[0].c, c.head(2), 1e-6));
  EXPECT_TRUE(test::MatrixNear(fit.out[1].c, c.tail(2), 1e-6));
  EXPECT_TRUE(test::MatrixNear(fit.e, rec.y - xf - X * c, 1e-6));
  // and near the values that generated the record
  EXPECT_NEAR(fit.out[0].c(0), 0.3, 0.01);
  EXPECT_NEAR(fit.out[0].c(1), -0.2, 0.01);
  EXPECT_NEAR(fit.out[1].c(0), 0.1, 0.02);
  EXPECT_NEAR(fit.out[1].c(1), 0.05, 0.02);
  EXPECT_TRUE(test::MatrixNear(fit.F, k.F, 0.05));
  // their standard errors: s2 (X'X)^-1 of that regression
  const Eigen::VectorXd r = rec.y - xf - X * c;
  const double s2 = r.squaredNorm() / (N - 4);
  const Eigen::VectorXd sd =
      (s2 * (X.transpose() * X).inverse()).diagonal().cwiseSqrt();
  EXPECT_TRUE(test::MatrixNear(fit.out[0].cstd, sd.head(2), 1e-6));
  EXPECT_EQ(fit.np, 5 + 4);
}

TEST(StructureFit, CensoredFitOfAKnownOutputSaturation) {
  // y = min(x + 5, hi): the fit with the saturation at its known level
  // (the record's level estimated with the model, as residtrace fits it)
  // comes much closer to the structure that generated the record than
  // the same fit without the saturation
  const int N = 2000;
  Known k(N);
  // the level: the 90th percentile of the unsaturated output
  std::vector<double> sorted(k.x.data(), k.x.data() + N);
  std::sort(sorted.begin(), sorted.end());
  const double hi = k.level + sorted[9 * N / 10];
  StructureRecord<double> rec;
  rec.u = k.u;
  rec.ts = k.ts;
  rec.y = (k.x.array() + k.level).cwiseMin(hi).matrix();
  int clipped = 0;
  for (int i = 0; i < N; ++i) clipped += rec.y(i) == hi;
  ASSERT_GT(clipped, N / 20);
  StructureModel<double> m = k.model(true);
  OutputTerm<double> sat;
  sat.kind = OutputTermKind::kSaturation;
  sat.c = vec({-std::numeric_limits<double>::infinity(), hi});
  m.out.push_back(sat);
  StructureFit<double> fit;
  ASSERT_TRUE(fit_structure<double>(m, rec, {vec({1, 2, 1})}, 30, &fit).ok());
  ASSERT_TRUE(fit.ok);
  EXPECT_FALSE(fit.out[1].fitted);  // the levels are the caller's
  EXPECT_EQ(fit.np, 5 + 1 + 1);     // theta, the level, the finite level
  m.out.pop_back();
  StructureFit<double> plain;
  ASSERT_TRUE(fit_structure<double>(m, rec, {vec({1, 2, 1})}, 30, &plain).ok());
  ASSERT_TRUE(plain.ok);
  const double censored = test::relative_error(fit.B[0], k.B1);
  const double ignored = test::relative_error(plain.B[0], k.B1);
  EXPECT_LT(censored, 0.2 * ignored);
  EXPECT_LT(std::abs(fit.out[0].c(0) - k.level),
            0.2 * std::abs(plain.out[0].c(0) - k.level));
  // e is y minus the saturated model output
  const Eigen::VectorXd xf =
      zoh(fit.B[0], fit.F, k.u.col(0), k.ts) +
      zoh(fit.B[1], fit.F, k.u.col(1).array().square().matrix(), k.ts);
  const Eigen::VectorXd yf =
      (xf.array() + fit.out[0].c(0)).cwiseMin(hi).matrix();
  EXPECT_TRUE(test::MatrixNear(fit.e, rec.y - yf, 1e-6));
}

TEST(StructureFit, MissingSamplesCarryNoError) {
  // a gap bridged by linear interpolation (as residtrace bridges it):
  // flagged missing, the bridged values carry no error and the estimate
  // comes closer to the truth than with the bridge taken as data
  const int N = 1500;
  Known k(N);
  StructureRecord<double> rec;
  rec.u = k.u;
  rec.ts = k.ts;
  rec.y = k.x;
  const int a = 299, b = 380;
  for (int i = a + 1; i < b; ++i) {
    rec.y(i) = k.x(a) + (k.x(b) - k.x(a)) * (i - a) / double(b - a);
  }
  StructureFit<double> as_data;
  ASSERT_TRUE(
      fit_structure<double>(k.model(false), rec, {vec({1, 2, 1})}, 30, &as_data)
          .ok());
  ASSERT_TRUE(as_data.ok);
  rec.missing.assign(N, false);
  for (int i = a + 1; i < b; ++i) rec.missing[i] = true;
  StructureFit<double> fit;
  ASSERT_TRUE(
      fit_structure<double>(k.model(false), rec, {vec({1, 2, 1})}, 30, &fit)
          .ok());
  ASSERT_TRUE(fit.ok);
  for (int i = a + 1; i < b; ++i) EXPECT_EQ(fit.e(i), 0);
  EXPECT_LT(test::relative_error(fit.F, k.F),
            0.2 * test::relative_error(as_data.F, k.F));
  EXPECT_LT(test::relative_error(fit.B[0], k.B1),
            0.2 * test::relative_error(as_data.B[0], k.B1));
}

TEST(StructureFit, BadStructuresAreIdentifiedErrors) {
  const int N = 100;
  Known k(N);
  StructureRecord<double> rec;
  rec.u = k.u;
  rec.ts = k.ts;
  rec.y = k.x;
  StructureFit<double> fit;
  StructureModel<double> m = k.model(false);
  m.fixed = {false};
  EXPECT_EQ(fit_structure<double>(m, rec, {}, 30, &fit).code(),
            ErrorCode::kDimensionMismatch);
  m = k.model(false);
  m.channels[0].col = 5;
  EXPECT_EQ(fit_structure<double>(m, rec, {}, 30, &fit).code(),
            ErrorCode::kBadInput);
  m = k.model(false);
  EXPECT_EQ(fit_structure<double>(m, rec, {vec({1, 2})}, 30, &fit).code(),
            ErrorCode::kDimensionMismatch);
  m.channels[0].kind = ChannelKind::kSignV;  // no velocity given
  EXPECT_EQ(fit_structure<double>(m, rec, {}, 30, &fit).code(),
            ErrorCode::kDimensionMismatch);
  EXPECT_FALSE(fit.ok);
}

}  // namespace
}  // namespace ctid::residtrace
