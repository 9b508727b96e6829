// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_x0.hpp:
//   - a first-order system 3 / (p + 2) started from x(0) = 0.5: its free
//     response 0.5 exp(-2 t) (written out here, not taken from the core)
//     in the residual is found, x0 = 0.5, and removes nearly all of it;
//   - a model estimating its initial state already, a validation record
//     that continues the estimation record and a closed loop give their
//     reasons; a residual of the wrong length is a Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_x0.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

ResidtraceModel<double> first_order() {
  ResidtraceModel<double> m;
  m.F = Eigen::Vector2d(1, 2);
  m.fixed = {false};
  StructureChannel<double> c;
  c.col = 0;
  c.nb = 1;
  c.B = Eigen::VectorXd::Constant(1, 3);
  m.channels.push_back(c);
  return m;
}

void record(ResidtraceModel<double>* cur, CandidateContext<double>* ctx) {
  const int N = 600;
  const std::vector<double> u = test::binary_input(N, 9, 31);
  ctx->D.u = Eigen::Map<const Eigen::VectorXd>(u.data(), N);
  ctx->D.ts = kTs;
  *cur = first_order();
  ModelSimulation<double> sim;
  ASSERT_TRUE(
      simulate_model<double>(*cur, ctx->D.u, kTs, nullptr, 1, nullptr, &sim)
          .ok());
  std::mt19937 gen(32);
  std::normal_distribution<double> noise(0.0, 1e-3);
  ctx->D.y = sim.y;
  for (int k = 0; k < N; ++k) {
    ctx->D.y(k) += 0.5 * std::exp(-2.0 * k * kTs) + noise(gen);
  }
  cur->estimate.e = ctx->D.y - sim.y;
}

TEST(ResidtraceCandidateX0, FindsTheInitialState) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(&cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(x0_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.effect, "initial_state");
  EXPECT_TRUE(c.model.x0);
  EXPECT_TRUE(c.insample);
  EXPECT_EQ(c.nadd, 1);
  EXPECT_EQ(c.variant, "x0 of 1 states fitted on each record");
  double x0 = 0, share = 0;
  for (const EvidenceField<double>& f : c.evidence.fields) {
    if (f.name == "value") x0 = f.value(0);
    if (f.name == "share_estimation") share = f.value(0);
  }
  EXPECT_NEAR(x0, 0.5, 5e-3);
  EXPECT_GT(share, 0.95);
  EXPECT_LE(share, 1);
  EXPECT_EQ(c.evidence.text.substr(0, 34), "the free response from x0 = 0.5 re")
      << c.evidence.text;
}

TEST(ResidtraceCandidateX0, NotApplicableBranchesAndBadInput) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(&cur, &ctx);
  Candidate<double> c;
  cur.x0 = true;
  ASSERT_TRUE(x0_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the initial state is estimated already");
  cur.x0 = false;
  ctx.validation_continues = true;
  ASSERT_TRUE(x0_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason.substr(0, 30), "the validation record continue");
  ctx.validation_continues = false;
  ctx.D.closed = true;
  ASSERT_TRUE(x0_candidate<double>(cur, ctx, &c).ok());
  EXPECT_EQ(c.reason, "not in closed loop");
  ctx.D.closed = false;
  cur.estimate.e.resize(5);
  EXPECT_FALSE(x0_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(x0_candidate<double>(cur, ctx, nullptr).ok());
}

}  // namespace
}  // namespace ctid::residtrace
