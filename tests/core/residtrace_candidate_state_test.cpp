// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/candidate_state.hpp, on
// records simulated by a Runge-Kutta integration written here (not the
// core's simulator):
//   - a first-order system with a quadratic term of the output in its
//     dynamics, y' = -a y + b u + g y^2: the candidate keeps a variant with
//     y^2, recovers g within a few standard deviations and writes it in
//     the evidence; without a positive output there is no sqrt variant;
//   - a tank, y' = b u - k sqrt(y) (a positive level): the variants
//     include sqrt(y) and the one kept beats the linear model's BIC;
//   - a cascade variant given fitted is compared by its BIC, and its
//     evidence reads its alpha, gamma and levels;
//   - the not-applicable branches give their reasons, bad input a Status
//     error.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_state.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

// y' = f(y, u) with u held over each interval, 20 RK4 steps an interval;
// y0 the initial output, plus white noise of the given deviation.
Eigen::VectorXd rk4(const std::function<double(double, double)>& f,
                    const Eigen::VectorXd& u, double y0, double noise,
                    unsigned seed) {
  const int sub = 20;
  const double h = kTs / sub;
  Eigen::VectorXd y(u.size());
  double x = y0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    y(k) = x;
    for (int s = 0; s < sub; ++s) {
      const double k1 = f(x, u(k)), k2 = f(x + h / 2 * k1, u(k));
      const double k3 = f(x + h / 2 * k2, u(k)), k4 = f(x + h * k3, u(k));
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  std::mt19937 gen(seed);
  std::normal_distribution<double> e(0.0, noise);
  for (Eigen::Index k = 0; k < y.size(); ++k) y(k) += e(gen);
  return y;
}

// A multi-level input: levels drawn uniformly in [lo, hi], each held for
// hold samples.
Eigen::VectorXd levels(int N, int hold, double lo, double hi, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(lo, hi);
  Eigen::VectorXd u(N);
  double v = d(gen);
  for (int k = 0; k < N; ++k) {
    if (k % hold == 0) v = d(gen);
    u(k) = v;
  }
  return u;
}

ResidtraceModel<double> first_order(double a, double b, int np) {
  ResidtraceModel<double> m;
  m.F = Eigen::Vector2d(1, a);
  m.fixed = {false};
  StructureChannel<double> c;
  c.col = 0;
  c.nb = 1;
  c.B = Eigen::VectorXd::Constant(1, b);
  m.channels.push_back(c);
  m.estimate.ok = true;
  m.estimate.np = np;
  return m;
}

CandidateContext<double> context(const Eigen::VectorXd& u,
                                 const Eigen::VectorXd& y) {
  CandidateContext<double> ctx;
  ctx.D.u = u;
  ctx.D.y = y;
  ctx.D.ysm = y;  // the output the output powers act on
  ctx.D.ts = kTs;
  ctx.fit.max_iterations = 20;
  ctx.fit.substeps = 10;
  return ctx;
}

TEST(ResidtraceCandidateState, RecoversAQuadraticTermOfTheOutput) {
  const double a = 2, b = 3, g = -0.5;
  const Eigen::VectorXd u = levels(1500, 40, -1, 1, 7);
  const Eigen::VectorXd y =
      rk4([&](double x, double v) { return -a * x + b * v + g * x * x; }, u, 0,
          2e-3, 8);
  const CandidateContext<double> ctx = context(u, y);
  Candidate<double> c;
  const Status s =
      state_candidate<double>(first_order(a, b, 2), ctx, nullptr, &c);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.effect, "state_nonlinearity");
  // no positive output: no sqrt(y) variant
  ASSERT_EQ(c.variants.size(), 3u);
  EXPECT_EQ(c.variants[0].variant, "output in the dynamics: y^2");
  ASSERT_NE(c.variant.find("y^2"), std::string::npos) << c.variant;
  // y^2's gain: the first of the output terms
  int first = -1, nlin = 0;
  for (std::size_t j = 0; j < c.model.channels.size(); ++j) {
    if (c.model.channels[j].kind != ChannelKind::kOutputPower) continue;
    if (first < 0) first = static_cast<int>(j);
    ++nlin;
  }
  ASSERT_EQ(c.model.channels[first].param, 2);
  EXPECT_EQ(c.nadd, nlin);
  const double gain = c.model.channels[first].B(0);
  ASSERT_EQ(c.evidence.fields[1].name, "value");
  ASSERT_EQ(c.evidence.fields[2].name, "std");
  const double sd = c.evidence.fields[2].value(0);
  EXPECT_DOUBLE_EQ(c.evidence.fields[1].value(0), gain);
  EXPECT_NEAR(gain, g, std::max(4 * sd, 0.02));
  EXPECT_NE(c.evidence.text.find(": coefficients "), std::string::npos)
      << c.evidence.text;
}

TEST(ResidtraceCandidateState, TankHasASquareRootVariant) {
  const double b = 1, k = 0.8;
  const Eigen::VectorXd u = levels(4000, 200, 0.5, 3, 11);
  const Eigen::VectorXd y =
      rk4([&](double x,
              double v) { return b * v - k * std::sqrt(std::max(x, 0.0)); },
          u, std::pow(u(0) / k, 2), 5e-3, 12);
  const CandidateContext<double> ctx = context(u, y);
  // the linear model of the record (its levels read from the record)
  ResidtraceModel<double> lin = first_order(0.3, 0.3, 2);
  ResidtraceModel<double> cur;
  ASSERT_TRUE(fit_model<double>(lin, ctx.D, {lin.F}, ctx.fit, &cur).ok());
  Candidate<double> c;
  ASSERT_TRUE(state_candidate<double>(cur, ctx, nullptr, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  ASSERT_EQ(c.variants.size(), 4u);
  EXPECT_EQ(c.variants[0].variant, "output in the dynamics: sqrt(y)");
  EXPECT_EQ(c.added_channels.size(),
            c.model.channels.size() - cur.channels.size());
  EXPECT_LT(c.model.estimate.bic, cur.estimate.bic - 100);
}

TEST(ResidtraceCandidateState, ComparesAGivenCascadeByItsBic) {
  const Eigen::VectorXd u = levels(600, 30, 1, 2, 3);
  const Eigen::VectorXd y =
      rk4([](double x, double v) { return -x + v; }, u, 1, 1e-3, 4);
  const CandidateContext<double> ctx = context(u, y);
  ResidtraceModel<double> cas = first_order(1, 1, 6);
  cas.has_phys = true;
  cas.phys.kind = PhysicalKind::kCascade;
  cas.phys.alpha = 0.25;
  cas.phys.gamma = 0.5;
  cas.phys.c = -0.1;
  cas.estimate.bic = -1e9;  // below any fit of the record
  cas.estimate.s2 = 1e-12;
  Candidate<double> c;
  ASSERT_TRUE(
      state_candidate<double>(first_order(1, 1, 2), ctx, &cas, &c).ok());
  ASSERT_TRUE(c.applicable);
  ASSERT_EQ(c.variants.size(), 5u);
  EXPECT_EQ(c.variant, "square-root outflows of a two-section cascade");
  EXPECT_EQ(c.chosen, 4);
  EXPECT_EQ(c.nadd, 4);
  EXPECT_EQ(c.evidence.text,
            "square-root outflows of a two-section cascade: alpha 0.25, "
            "gamma 0.5, output level -0.1");
  ASSERT_EQ(c.evidence.fields[1].value.size(), 3);
  EXPECT_TRUE(std::isinf(c.evidence.fields[1].value(2)));  // no inner level
  // a cascade that failed is no variant
  cas.estimate.ok = false;
  ASSERT_TRUE(
      state_candidate<double>(first_order(1, 1, 2), ctx, &cas, &c).ok());
  EXPECT_EQ(c.variants.size(), 4u);
}

TEST(ResidtraceCandidateState, NotApplicableWithAnOutputNonlinearity) {
  const Eigen::VectorXd u = levels(200, 20, -1, 1, 5);
  const CandidateContext<double> ctx = context(u, u);
  ResidtraceModel<double> m = first_order(1, 1, 2);
  StructureChannel<double> p;
  p.kind = ChannelKind::kOutputPower;
  p.col = -1;
  p.param = 2;
  p.B = Eigen::VectorXd::Zero(1);
  m.channels.push_back(p);
  Candidate<double> c;
  ASSERT_TRUE(state_candidate<double>(m, ctx, nullptr, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the model has a nonlinearity of the output already");
  m = first_order(1, 1, 2);
  m.has_phys = true;
  ASSERT_TRUE(state_candidate<double>(m, ctx, nullptr, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the model has a nonlinearity of the output already");
}

TEST(ResidtraceCandidateState, BadInput) {
  const Eigen::VectorXd u = levels(200, 20, -1, 1, 5);
  CandidateContext<double> ctx = context(u, u);
  const ResidtraceModel<double> m = first_order(1, 1, 2);
  EXPECT_FALSE(state_candidate<double>(m, ctx, nullptr, nullptr).ok());
  Candidate<double> c;
  // a cascade variant that is no physical realisation
  EXPECT_EQ(state_candidate<double>(m, ctx, &m, &c).code(),
            ErrorCode::kBadInput);
  ctx.D.y.resize(0);
  EXPECT_EQ(state_candidate<double>(m, ctx, nullptr, &c).code(),
            ErrorCode::kBadInput);
}

TEST(ResidtraceCandidateState, Mat2strWritesAsOctave) {
  using candidate_detail::mat2str;
  EXPECT_EQ(mat2str<double>(Eigen::VectorXd::Constant(1, -0.123456), 4),
            "-0.1235");
  EXPECT_EQ(mat2str<double>(Eigen::Vector2d(1.5e-7, 2), 2), "[1.5e-07 2]");
}

}  // namespace
}  // namespace ctid::residtrace
