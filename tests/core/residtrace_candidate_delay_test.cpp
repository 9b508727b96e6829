// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_delay.hpp:
//   - a first-order system behind a delay of 3 whole samples, modelled
//     without it: the candidate finds nk = 3 (the fraction is not taken:
//     it does not lower the BIC by log N), with the delay in seconds;
//   - behind 2.5 samples (the held input delayed by half a sample, as the
//     channel signals form it): the refined delay lies within 0.1 sample;
//   - without a delay to try, and with the residual of the wrong length,
//     the reason and the Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_delay.hpp"
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
