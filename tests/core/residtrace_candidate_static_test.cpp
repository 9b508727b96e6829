// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/candidate_static.hpp, on
// records simulated by a Runge-Kutta integration written here (not the
// core's simulator):
//   - a Hammerstein system, B(p)/F(p) (u + a2 u^2 + a3 u^3) with nb = 2:
//     the candidate keeps the HSRIVC variant and recovers a2, a3 within a
//     few standard deviations, with nf + nb + 2 parameters;
//   - a first-order system behind a saturation of its input at +-0.8: a
//     clip variant is kept and its refined level lies near 0.8;
//   - a Wiener system y = x + 0.2 x^2: the output polynomial is kept with
//     c2 near 0.2;
//   - a two-level input leaves the output variant only; a model with a
//     static nonlinearity already is not applicable; bad input gives a
//     Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_static.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

// The output of the state-space system x' = A x + b w(u), y = c x from
// rest, u held over each interval, 20 RK4 steps an interval, plus white
// noise of the given deviation.
Eigen::VectorXd rk4(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                    const Eigen::RowVectorXd& c,
                    const std::function<double(double)>& w,
                    const Eigen::VectorXd& u, double noise, unsigned seed) {
  const int sub = 20;
  const double h = kTs / sub;
  Eigen::VectorXd y(u.size()), x = Eigen::VectorXd::Zero(A.rows());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    y(k) = c * x;
    const Eigen::VectorXd f = b * w(u(k));
    for (int s = 0; s < sub; ++s) {
      const Eigen::VectorXd k1 = A * x + f, k2 = A * (x + h / 2 * k1) + f;
      const Eigen::VectorXd k3 = A * (x + h / 2 * k2) + f,
                            k4 = A * (x + h * k3) + f;
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  std::mt19937 gen(seed);
  std::normal_distribution<double> e(0.0, noise);
  for (Eigen::Index k = 0; k < y.size(); ++k) y(k) += e(gen);
  return y;
}

// First order: y' = -a y + b w(u).
Eigen::VectorXd first_order_output(double a, double b,
                                   const std::function<double(double)>& w,
                                   const Eigen::VectorXd& u, double noise,
                                   unsigned seed) {
  return rk4(Eigen::MatrixXd::Constant(1, 1, -a),
             Eigen::VectorXd::Constant(1, b), Eigen::RowVectorXd::Ones(1), w, u,
             noise, seed);
}

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

ResidtraceModel<double> model(const Eigen::VectorXd& F,
                              const Eigen::VectorXd& B) {
  ResidtraceModel<double> m;
  m.F = F;
  m.fixed.assign(static_cast<std::size_t>(F.size() - 1), false);
  StructureChannel<double> c;
  c.col = 0;
  c.nb = static_cast<int>(B.size());
  c.B = B;
  m.channels.push_back(c);
  m.estimate.ok = true;
  m.estimate.np = static_cast<int>(F.size() - 1 + B.size());
  return m;
}

CandidateContext<double> context(const Eigen::VectorXd& u,
                                 const Eigen::VectorXd& y) {
  CandidateContext<double> ctx;
  ctx.D.u = u;
  ctx.D.y = y;
  ctx.D.ts = kTs;
  ctx.fit.max_iterations = 20;
  ctx.fit.substeps = 1;
  return ctx;
}

TEST(ResidtraceCandidateStatic, HammersteinByHsrivc) {
  // F = p^2 + 3 p + 2, B = p + 3 in controllable canonical form
  Eigen::MatrixXd A(2, 2);
  A << 0, 1, -2, -3;
  const Eigen::RowVectorXd c = Eigen::RowVector2d(3, 1);
  const double a2 = 0.5, a3 = 0.3;
  const Eigen::VectorXd u = levels(3000, 20, -1.5, 1.5, 21);
  const Eigen::VectorXd y = rk4(
      A, Eigen::Vector2d(0, 1), c,
      [&](double v) { return v + a2 * v * v + a3 * v * v * v; }, u, 0.01, 22);
  const CandidateContext<double> ctx = context(u, y);
  const ResidtraceModel<double> cur =
      model(Eigen::Vector3d(1, 3, 2), Eigen::Vector2d(1, 3));
  Candidate<double> cand;
  HammersteinPart<double> part;
  ASSERT_TRUE(static_candidate<double>(cur, {"u1"}, ctx, &cand, &part).ok());
  ASSERT_TRUE(cand.applicable) << cand.reason;
  EXPECT_EQ(cand.variant, "u1 + a2 u1^2 + a3 u1^3 (Hammerstein, hsrivc)");
  ASSERT_TRUE(part.present);
  EXPECT_DOUBLE_EQ(part.alpha(0), 1);
  EXPECT_NEAR(part.alpha(1), a2, 4 * part.sd(1) + 1e-3);
  EXPECT_NEAR(part.alpha(2), a3, 4 * part.sd(2) + 1e-3);
  EXPECT_EQ(cand.nadd, 2);  // nf + nb + 2 against nf + nb
  ASSERT_EQ(cand.model.channels.size(), 3u);
  // the products a_k B in the power channels, B in the input's
  const Eigen::VectorXd& B = cand.model.channels[0].B;
  EXPECT_LT((cand.model.channels[1].B - part.alpha(1) * B).norm(),
            1e-12 * B.norm());
  EXPECT_EQ(cand.model.estimate.theta.size(), 2 + 3 * 2);
  EXPECT_EQ(cand.added_channels, (std::vector<std::string>{"u1^2", "u1^3"}));
  EXPECT_NE(cand.evidence.text.find("Hammerstein u + a2 u^2 + a3 u^3: a2 = "),
            std::string::npos);
}

TEST(ResidtraceCandidateStatic, InputSaturationIsAClipNearItsLevel) {
  const double level = 0.8;
  const Eigen::VectorXd u = levels(3000, 40, -2, 2, 31);
  const Eigen::VectorXd y = first_order_output(
      1, 2, [&](double v) { return std::max(-level, std::min(level, v)); }, u,
      0.005, 32);
  const CandidateContext<double> ctx = context(u, y);
  const ResidtraceModel<double> cur =
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(1, 1));
  Candidate<double> cand;
  HammersteinPart<double> part;
  ASSERT_TRUE(static_candidate<double>(cur, {"u1"}, ctx, &cand, &part).ok());
  ASSERT_TRUE(cand.applicable) << cand.reason;
  EXPECT_FALSE(part.present);
  ASSERT_EQ(cand.variant.rfind("u1 clipped at +-", 0), 0u) << cand.variant;
  ASSERT_EQ(cand.model.channels.back().kind, ChannelKind::kClip);
  const double L = cand.model.channels.back().param;
  EXPECT_NEAR(L, level, 0.05 * level);
  // the variant's name and the channel's carry the level kept
  EXPECT_EQ(cand.variant,
            "u1 clipped at +-" + candidate_detail::num("%.4g", L));
  EXPECT_EQ(cand.added_channels.back(),
            "clip(u1, " + candidate_detail::num("%.3g", L) + ")");
  // the clipped channel carries the gain: y' = -y + 2 sat(u)
  EXPECT_NEAR(cand.model.channels.back().B(0), 2, 0.1);
  EXPECT_NEAR(cand.model.channels[0].B(0), 0, 0.1);
  EXPECT_EQ(cand.nadd, 1);
}

TEST(ResidtraceCandidateStatic, WienerOutputPolynomial) {
  const Eigen::VectorXd u = levels(3000, 40, -1.5, 1.5, 41);
  Eigen::VectorXd x = first_order_output(
      1, 1, [](double v) { return v; }, u, 0, 0);
  std::mt19937 gen(42);
  std::normal_distribution<double> e(0.0, 0.005);
  Eigen::VectorXd y(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    y(k) = x(k) + 0.2 * x(k) * x(k) + e(gen);
  }
  const CandidateContext<double> ctx = context(u, y);
  const ResidtraceModel<double> cur =
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(1, 1));
  Candidate<double> cand;
  HammersteinPart<double> part;
  ASSERT_TRUE(static_candidate<double>(cur, {"u1"}, ctx, &cand, &part).ok());
  ASSERT_TRUE(cand.applicable) << cand.reason;
  EXPECT_EQ(cand.variant, "output: c2 x^2 + c3 x^3");
  const OutputTerm<double>& o = cand.model.out.back();
  EXPECT_NEAR(o.c(0), 0.2, 4 * o.cstd(0) + 0.01);
  EXPECT_NEAR(o.c(1), 0, 4 * o.cstd(1) + 0.01);
  EXPECT_EQ(cand.nadd, 2);
}

TEST(ResidtraceCandidateStatic, TwoLevelInputLeavesTheOutputVariant) {
  Eigen::VectorXd u = levels(600, 30, -1, 1, 51);
  for (Eigen::Index k = 0; k < u.size(); ++k) u(k) = u(k) > 0 ? 1 : -1;
  const Eigen::VectorXd y = first_order_output(
      1, 1, [](double v) { return v; }, u, 0.01, 52);
  const CandidateContext<double> ctx = context(u, y);
  const ResidtraceModel<double> cur =
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(1, 1));
  Candidate<double> cand;
  HammersteinPart<double> part;
  ASSERT_TRUE(static_candidate<double>(cur, {"u1"}, ctx, &cand, &part).ok());
  ASSERT_EQ(cand.variants.size(), 1u);
  EXPECT_EQ(cand.variants[0].variant, "output: c2 x^2 + c3 x^3");
}

TEST(ResidtraceCandidateStatic, NotApplicableAndBadInput) {
  const Eigen::VectorXd u = levels(300, 30, -1, 1, 61);
  const CandidateContext<double> ctx = context(u, u);
  ResidtraceModel<double> cur =
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(1, 1));
  Candidate<double> cand;
  HammersteinPart<double> part;
  EXPECT_EQ(
      static_candidate<double>(cur, {"u1", "u2"}, ctx, &cand, &part).code(),
      ErrorCode::kDimensionMismatch);
  EXPECT_FALSE(static_candidate<double>(cur, {"u1"}, ctx, nullptr, &part).ok());
  cur.channels[0].col = 3;  // no such input column
  EXPECT_EQ(static_candidate<double>(cur, {"u1"}, ctx, &cand, &part).code(),
            ErrorCode::kBadInput);
  cur.channels[0].col = 0;
  StructureChannel<double> p = cur.channels[0];
  p.kind = ChannelKind::kPower;
  p.param = 2;
  cur.channels.push_back(p);
  ASSERT_TRUE(
      static_candidate<double>(cur, {"u1", "u1^2"}, ctx, &cand, &part).ok());
  EXPECT_FALSE(cand.applicable);
  EXPECT_EQ(cand.reason, "the model has a static nonlinearity already");
}

TEST(ResidtraceCandidateStatic, GridQuantileIsTheRoundedOrderStatistic) {
  std::vector<double> x = {10, 9, 8, 7, 6, 5, 4, 3, 2, 1};
  EXPECT_EQ(static_detail::grid_quantile<double>(x, 0.3), 3);
  EXPECT_EQ(static_detail::grid_quantile<double>(x, 0.95), 10);  // 9.5 up
  EXPECT_EQ(static_detail::grid_quantile<double>(x, 0.01), 1);
}

}  // namespace
}  // namespace ctid::residtrace
