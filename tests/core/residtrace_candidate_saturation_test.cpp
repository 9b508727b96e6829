// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_saturation.hpp and
// physical_model.hpp:
//   - saturation_candidate finds an output saturation of known level on a
//     record of a second-order system clipped above, the level within 2 %
//     and the share of clipped samples near the one of the noise-free
//     record; it finds a clipped inner node of a two-section system (the
//     upstream pole, the level within 4 %, the downstream pole); it is
//     not applicable to a model with a saturation already,
//     and rejects errors of the wrong length;
//   - sample_quantile against quantiles worked by hand (Hazen's rule);
//   - cascade_template: the linearisation of the cascade started from a
//     linear model has that model's poles and static gain (linear nodes:
//     an identity of cascade_from_linear), and the reasons it gives when
//     the model has no cascade realisation;
//   - fit_physical_model recovers the levels of an end stop from a record
//     simulated with them, started from levels 20 % off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_saturation.hpp"
#include "ctid/apps/residtrace/physical_model.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

ResidtraceModel<double> linear(const Eigen::VectorXd& F,
                               const Eigen::VectorXd& B) {
  ResidtraceModel<double> m;
  m.F = F;
  m.fixed.assign(static_cast<std::size_t>(F.size() - 1), false);
  StructureChannel<double> c;
  c.col = 0;
  c.nb = static_cast<int>(B.size());
  c.B = B;
  m.channels.push_back(c);
  return m;
}

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) r(i++) = x;
  return r;
}

Eigen::VectorXd simulate(const ResidtraceModel<double>& m,
                         const Eigen::MatrixXd& u) {
  ModelSimulation<double> sim;
  EXPECT_TRUE(
      simulate_model<double>(m, u, kTs, nullptr, 1, nullptr, &sim).ok());
  return sim.y;
}

CandidateContext<double> record(const Eigen::VectorXd& y,
                                const Eigen::MatrixXd& u) {
  CandidateContext<double> ctx;
  ctx.D.u = u;
  ctx.D.y = y;
  ctx.D.ysm = y;
  ctx.D.ts = kTs;
  ctx.fit.max_iterations = 20;
  ctx.fit.substeps = 1;
  return ctx;
}

TEST(ResidtraceSaturation, FindsAnOutputLevel) {
  const int N = 1500;
  const std::vector<double> us = test::binary_input(N, 40, 5);
  const Eigen::MatrixXd u = Eigen::Map<const Eigen::VectorXd>(us.data(), N);
  const ResidtraceModel<double> truth =
      linear(vec({1, 1.6, 4}), vec({4}));  // static gain 1
  const Eigen::VectorXd x = simulate(truth, u);
  const double hi = 0.6;
  std::mt19937 gen(11);
  std::normal_distribution<double> noise(0.0, 0.005);
  Eigen::VectorXd y(N);
  int clipped = 0;
  for (int k = 0; k < N; ++k) {
    y(k) = std::min(x(k), hi) + noise(gen);
    clipped += x(k) >= hi ? 1 : 0;
  }
  ASSERT_GT(clipped, N / 20);  // the level is active
  CandidateContext<double> ctx = record(y, u);
  ResidtraceModel<double> cur = truth;  // the linear model, unclipped
  cur.estimate.e = y - x;
  cur.estimate.np = 2;
  Candidate<double> c;
  ASSERT_TRUE(saturation_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.variant, "output, upper level");
  int k = -1;
  for (std::size_t i = 0; i < c.model.out.size(); ++i) {
    if (c.model.out[i].kind == OutputTermKind::kSaturation) k = int(i);
  }
  ASSERT_GE(k, 0);
  EXPECT_NEAR(c.model.out[k].c(1), hi, 0.02 * hi);
  EXPECT_TRUE(std::isinf(c.model.out[k].c(0)));
  const EvidenceField<double>* share = nullptr;
  for (const auto& f : c.evidence.fields) {
    if (f.name == "share") share = &f;
  }
  ASSERT_NE(share, nullptr);
  EXPECT_NEAR(share->value(0), double(clipped) / N, 0.03);
  EXPECT_NE(c.evidence.text.find("output saturated at [-Inf, 0.6"),
            std::string::npos)
      << c.evidence.text;
  EXPECT_EQ(c.nadd, c.model.estimate.np - 2);
}

TEST(ResidtraceSaturation, FindsAnInnerNodeLevel) {
  // y = 2 / (p + 1) clip(z), z = 3 / (p + 3) u clipped above at 0.5
  const int N = 2000;
  const std::vector<double> us = test::binary_input(N, 40, 21);
  const Eigen::MatrixXd u = Eigen::Map<const Eigen::VectorXd>(us.data(), N);
  ResidtraceModel<double> node = linear(vec({1, 1}), vec({2}));
  StructureChannel<double>& ch = node.channels[0];
  ch.kind = ChannelKind::kNode;
  ch.node_f = vec({1, 3});
  ch.node_ts = kTs;
  ch.node_hi = 0.5;
  const Eigen::VectorXd yc = simulate(node, u);
  std::mt19937 gen(4);
  std::normal_distribution<double> noise(0.0, 0.005);
  Eigen::VectorXd y = yc;
  for (int k = 0; k < N; ++k) y(k) += noise(gen);
  // the current model: the linear cascade without the clip
  const ResidtraceModel<double> cur0 = linear(vec({1, 4, 3}), vec({6}));
  ResidtraceModel<double> cur = cur0;
  cur.estimate.e = y - simulate(cur0, u);
  cur.estimate.np = 3;
  CandidateContext<double> ctx = record(y, u);
  Candidate<double> c;
  ASSERT_TRUE(saturation_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.variant.rfind("inner node after pole(s) -3", 0), 0u) << c.variant;
  ASSERT_EQ(c.model.channels.size(), 1u);
  const StructureChannel<double>& k = c.model.channels[0];
  ASSERT_EQ(k.kind, ChannelKind::kNode);
  EXPECT_NEAR(k.node_hi, 0.5, 0.02);
  EXPECT_NEAR(k.node_f(1), 3, 1e-9);
  ASSERT_EQ(c.model.F.size(), 2);
  EXPECT_NEAR(c.model.F(1) / c.model.F(0), 1, 0.05);
}

TEST(ResidtraceSaturation, NotApplicableAndBadInput) {
  const int N = 200;
  const std::vector<double> us = test::binary_input(N, 10, 3);
  const Eigen::MatrixXd u = Eigen::Map<const Eigen::VectorXd>(us.data(), N);
  ResidtraceModel<double> cur = linear(vec({1, 2}), vec({2}));
  const Eigen::VectorXd y = simulate(cur, u);
  CandidateContext<double> ctx = record(y, u);
  cur.estimate.e = Eigen::VectorXd::Zero(N);
  ResidtraceModel<double> sat = cur;
  OutputTerm<double> o;
  o.kind = OutputTermKind::kSaturation;
  o.c = vec({-1, 1});
  o.cstd = vec({0, 0});
  sat.out.push_back(o);
  Candidate<double> c;
  ASSERT_TRUE(saturation_candidate<double>(sat, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the model has a saturation already");
  ResidtraceModel<double> bad = cur;
  bad.estimate.e = Eigen::VectorXd::Zero(N - 1);
  EXPECT_FALSE(saturation_candidate<double>(bad, ctx, &c).ok());
  EXPECT_FALSE(saturation_candidate<double>(cur, ctx, nullptr).ok());
}

TEST(ResidtraceSaturation, QuantilesByHazensRule) {
  const Eigen::VectorXd x = vec({5, 1, 4, 2, 3});
  EXPECT_DOUBLE_EQ(sample_quantile<double>(x, 0.5), 3);
  EXPECT_DOUBLE_EQ(sample_quantile<double>(x, 0.7), 4);  // (4 - 1/2) / 5
  EXPECT_DOUBLE_EQ(sample_quantile<double>(x, 0.6), 3.5);
  EXPECT_DOUBLE_EQ(sample_quantile<double>(x, 0.05), 1);  // below the first
  EXPECT_DOUBLE_EQ(sample_quantile<double>(x, 0.99), 5);
  const Eigen::VectorXd w = vec({2, NAN, 4});  // NaN ignored
  EXPECT_DOUBLE_EQ(sample_quantile<double>(w, 0.5), 3);
}

TEST(ResidtraceSaturation, CascadeTemplateKeepsPolesAndGain) {
  const int N = 600;
  const std::vector<double> us = test::binary_input(N, 30, 7);
  Eigen::MatrixXd u = Eigen::Map<const Eigen::VectorXd>(us.data(), N);
  u.array() += 2;  // a positive inflow
  // (p + 1)(p + 3), static gain 2
  const ResidtraceModel<double> cur = linear(vec({1, 4, 3}), vec({6}));
  const Eigen::VectorXd y = simulate(cur, u).array() + 0.5;
  CandidateContext<double> ctx = record(y, u);
  ResidtraceModel<double> t;
  bool made = false;
  std::string why;
  ASSERT_TRUE(
      cascade_template<double>(cur, ctx.D, false, false, &t, &made, &why).ok());
  ASSERT_TRUE(made) << why;
  ASSERT_TRUE(t.has_phys);
  EXPECT_EQ(t.phys.kind, PhysicalKind::kCascade);
  ASSERT_EQ(t.F.size(), 3);
  EXPECT_NEAR(t.F(1), 4, 1e-12);
  EXPECT_NEAR(t.F(2), 3, 1e-12);
  // linear nodes: gain b / (alpha gamma) = K = 2
  EXPECT_NEAR(t.phys.b(0) / (t.phys.alpha * t.phys.gamma), 2, 1e-12);
  EXPECT_NEAR(t.phys.h0, y(0), 1e-12);  // c = 0 for linear nodes
  // with the inner level: one of the quantiles of the inner state
  ASSERT_TRUE(
      cascade_template<double>(cur, ctx.D, true, true, &t, &made, &why).ok());
  ASSERT_TRUE(made) << why;
  EXPECT_TRUE(std::isfinite(t.phys.hi));
  EXPECT_TRUE(t.phys.has_spill);
  EXPECT_EQ(t.phys.spill, 0);
  // no realisation: closed loop, an unstable pole, other channels
  CandidateContext<double> closed = ctx;
  closed.D.closed = true;
  ASSERT_TRUE(
      cascade_template<double>(cur, closed.D, true, true, &t, &made, &why)
          .ok());
  EXPECT_FALSE(made);
  EXPECT_EQ(why, "a cascade realisation in open loop only");
  const ResidtraceModel<double> unstable = linear(vec({1, -1}), vec({1}));
  ASSERT_TRUE(
      cascade_template<double>(unstable, ctx.D, true, true, &t, &made, &why)
          .ok());
  EXPECT_FALSE(made);
  EXPECT_EQ(why, "integrators or unstable poles");
  ResidtraceModel<double> signv = cur;
  signv.channels[0].kind = ChannelKind::kSignV;
  ASSERT_TRUE(
      cascade_template<double>(signv, ctx.D, true, true, &t, &made, &why).ok());
  EXPECT_FALSE(made);
  EXPECT_EQ(why, "channels other than inputs");
}

TEST(ResidtraceSaturation, EndStopLevelsRecovered) {
  const int N = 1200;
  const std::vector<double> us = test::binary_input(N, 50, 9);
  const Eigen::MatrixXd u = Eigen::Map<const Eigen::VectorXd>(us.data(), N);
  ResidtraceModel<double> truth = linear(vec({1, 1.2, 4}), vec({4}));
  truth.has_phys = true;
  truth.phys.kind = PhysicalKind::kStop;
  truth.phys.lo = -0.5;
  truth.phys.hi = 0.7;
  truth.phys.substeps = 20;
  const Eigen::VectorXd y = simulate(truth, u);
  int at_lo = 0, at_hi = 0;  // both stops reached
  for (int k = 0; k < N; ++k) {
    at_lo += y(k) <= -0.5 + 1e-9 ? 1 : 0;
    at_hi += y(k) >= 0.7 - 1e-9 ? 1 : 0;
  }
  ASSERT_GT(at_lo, N / 20);
  ASSERT_GT(at_hi, N / 20);
  ResidtraceModel<double> start = truth;
  start.phys.lo = -0.6;
  start.phys.hi = 0.84;
  start.phys.yscale = physical_model_detail::sample_std<double>(y);
  CandidateContext<double> ctx = record(y, u);
  ResidtraceModel<double> m;
  ASSERT_TRUE(fit_physical_model<double>(start, ctx.D, 50, &m).ok());
  ASSERT_TRUE(m.estimate.ok);
  EXPECT_NEAR(m.phys.lo, -0.5, 0.005);
  EXPECT_NEAR(m.phys.hi, 0.7, 0.007);
  // np: the free f's, b0 and the two levels; the linear part's theta
  EXPECT_EQ(m.estimate.np, 5);
  EXPECT_EQ(m.estimate.theta.size(), 3);
  EXPECT_EQ(m.phys.theta.size(), 5);
  EXPECT_EQ(m.estimate.e.size(), N);
}

}  // namespace
}  // namespace ctid::residtrace
