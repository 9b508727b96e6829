// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_delay.hpp:
//   - a first-order system behind a delay of 3 whole samples, modelled
//     without it: the candidate finds nk = 3 (the fraction is not taken:
//     it does not lower the BIC by log N), with the delay in seconds;
//   - behind 2.5 samples (the held input delayed by half a sample, as the
//     channel signals form it): the refined delay lies within 0.1 sample;
//   - a second-order system with end stops (a physical realisation) behind
//     a delay of 2 whole samples, its realisation fitted without it: the
//     candidate refits the realisation at the whole delays and finds
//     nk = 2, the stops' levels within 1 % of the travel of the truth and
//     a BIC below the current model's;
//   - without a delay to try, and with the residual of the wrong length,
//     the reason and the Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_delay.hpp"
#include "ctid/apps/residtrace/physical_model.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

ResidtraceModel<double> first_order(int nk, double frac) {
  ResidtraceModel<double> m;
  m.F = Eigen::Vector2d(1, 2);
  m.fixed = {false};
  StructureChannel<double> c;
  c.col = 0;
  c.nb = 1;
  c.nk = nk;
  c.param = frac;
  c.B = Eigen::VectorXd::Constant(1, 3);
  m.channels.push_back(c);
  return m;
}

// The record of the delayed system with a little white noise; cur the
// model without the delay, with its residual.
void record(int nk, double frac, ResidtraceModel<double>* cur,
            CandidateContext<double>* ctx) {
  const int N = 1500;
  const std::vector<double> u = test::binary_input(N, 7, 21);
  ctx->D.u = Eigen::Map<const Eigen::VectorXd>(u.data(), N);
  ctx->D.ts = kTs;
  ModelSimulation<double> sim, sim0;
  ASSERT_TRUE(simulate_model<double>(first_order(nk, frac), ctx->D.u, kTs,
                                     nullptr, 1, nullptr, &sim)
                  .ok());
  *cur = first_order(0, 0);
  ASSERT_TRUE(
      simulate_model<double>(*cur, ctx->D.u, kTs, nullptr, 1, nullptr, &sim0)
          .ok());
  std::mt19937 gen(22);
  std::normal_distribution<double> noise(0.0, 0.01);
  ctx->D.y = sim.y;
  for (int k = 0; k < N; ++k) ctx->D.y(k) += noise(gen);
  ctx->D.ysm = ctx->D.y;
  ctx->fit.max_iterations = 20;
  ctx->fit.substeps = 1;
  ctx->max_delay = 5;
  ctx->max_lag = 25;
  ctx->channel_names = {"u1"};
  cur->estimate.e = ctx->D.y - sim0.y;
}

double field(const Candidate<double>& c, const char* name) {
  for (const EvidenceField<double>& f : c.evidence.fields) {
    if (f.name == name) return f.value(0);
  }
  return std::nan("");
}

TEST(ResidtraceCandidateDelay, FindsAWholeSampleDelay) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(3, 0, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(delay_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.variant, "nk = 3 on u1");
  EXPECT_EQ(c.nadd, 1);
  EXPECT_EQ(c.model.channels[0].nk, 3);
  EXPECT_EQ(c.model.channels[0].param, 0);
  EXPECT_NEAR(c.model.F(1), 2, 0.02);
  EXPECT_DOUBLE_EQ(field(c, "value"), 3);
  EXPECT_DOUBLE_EQ(field(c, "physical"), 3 * kTs);
  EXPECT_EQ(c.evidence.text.substr(0, 40),
            "delay nk = 3 samples (0.15 s, +3); resid")
      << c.evidence.text;
}

TEST(ResidtraceCandidateDelay, RefinesAFractionalDelay) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(2, 0.5, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(delay_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_NEAR(field(c, "value"), 2.5, 0.1) << c.variant;
  EXPECT_NEAR(c.model.F(1), 2, 0.05);
}

TEST(ResidtraceCandidateDelay, FindsTheDelayOfAnEndStop) {
  const int N = 1200;
  const std::vector<double> us = test::binary_input(N, 50, 9);
  CandidateContext<double> ctx;
  ctx.D.u = Eigen::Map<const Eigen::VectorXd>(us.data(), N);
  ctx.D.ts = kTs;
  ResidtraceModel<double> truth;
  truth.F = Eigen::Vector3d(1, 1.2, 4);
  truth.fixed = {false, false};
  StructureChannel<double> ch;
  ch.col = 0;
  ch.nb = 1;
  ch.nk = 2;
  ch.B = Eigen::VectorXd::Constant(1, 4);
  truth.channels.push_back(ch);
  truth.has_phys = true;
  truth.phys.kind = PhysicalKind::kStop;
  truth.phys.lo = -0.5;
  truth.phys.hi = 0.7;
  truth.phys.substeps = 20;
  Eigen::VectorXd y, z;
  ASSERT_TRUE(
      simulate_physical_model<double>(truth, ctx.D.u, kTs, &y, &z).ok());
  std::mt19937 gen(5);
  std::normal_distribution<double> noise(0.0, 0.005);
  for (int k = 0; k < N; ++k) y(k) += noise(gen);
  ctx.D.y = y;
  ctx.D.ysm = y;
  ctx.fit.max_iterations = 20;
  ctx.fit.substeps = 1;
  ctx.max_delay = 4;
  ctx.max_lag = 25;
  ctx.channel_names = {"u1"};
  // the current model: the realisation fitted without the delay
  ResidtraceModel<double> start = truth;
  start.channels[0].nk = 0;
  start.phys.lo = -0.6;
  start.phys.hi = 0.84;
  start.phys.yscale = physical_model_detail::sample_std<double>(y);
  ResidtraceModel<double> cur;
  ASSERT_TRUE(fit_physical_model<double>(start, ctx.D, 20, &cur).ok());
  ASSERT_TRUE(cur.estimate.ok);
  Candidate<double> c;
  ASSERT_TRUE(delay_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.variant, "nk = 2 on u1");
  ASSERT_TRUE(c.model.has_phys);
  EXPECT_EQ(c.model.channels[0].nk, 2);
  EXPECT_EQ(c.model.channels[0].param, 0);
  EXPECT_NEAR(c.model.phys.lo, -0.5, 0.012);
  EXPECT_NEAR(c.model.phys.hi, 0.7, 0.012);
  EXPECT_NEAR(c.model.F(1), 1.2, 0.05);
  EXPECT_NEAR(c.model.F(2), 4, 0.1);
  EXPECT_LT(c.model.estimate.bic, cur.estimate.bic);
  EXPECT_DOUBLE_EQ(field(c, "value"), 2);
  EXPECT_DOUBLE_EQ(field(c, "physical"), 2 * kTs);
}

TEST(ResidtraceCandidateDelay, NothingToTryAndBadInput) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(1, 0, &cur, &ctx);
  ctx.max_delay = 0;
  Candidate<double> c;
  ASSERT_TRUE(delay_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "no delay to try");
  ctx.max_delay = 2;
  cur.estimate.e.resize(10);
  EXPECT_FALSE(delay_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(delay_candidate<double>(cur, ctx, nullptr).ok());
}

}  // namespace
}  // namespace ctid::residtrace
