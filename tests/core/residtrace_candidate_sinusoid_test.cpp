// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_sinusoid.hpp:
//   - a sinusoid of known frequency and amplitude added to the output of a
//     first-order system is found: its frequency within a tenth of a bin,
//     its amplitude within a few standard deviations, Fisher's p small;
//   - too few samples, and records too short for two cycles of any
//     period, give their reasons;
//   - a residual of the wrong length is a Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_sinusoid.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;
constexpr double kPi = 3.141592653589793;

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

// The record of the model plus a sin(w t + phase) and a little white
// noise; cur the model with its residual (the sinusoid and the noise).
void record(int N, double amp, double w, ResidtraceModel<double>* cur,
            CandidateContext<double>* ctx) {
  *cur = first_order();
  const std::vector<double> u = test::binary_input(N, 9, 11);
  ctx->D.u = Eigen::Map<const Eigen::VectorXd>(u.data(), N);
  ctx->D.ts = kTs;
  ModelSimulation<double> sim;
  ASSERT_TRUE(
      simulate_model<double>(*cur, ctx->D.u, kTs, nullptr, 1, nullptr, &sim)
          .ok());
  std::mt19937 gen(12);
  std::normal_distribution<double> noise(0.0, 0.02);
  ctx->D.y = sim.y;
  for (int k = 0; k < N; ++k) {
    ctx->D.y(k) += amp * std::sin(w * k * kTs + 0.4) + noise(gen);
  }
  ctx->D.ysm = ctx->D.y;
  ctx->fit.max_iterations = 20;
  ctx->fit.substeps = 1;
  ctx->validation_samples = N;
  cur->estimate.e = ctx->D.y - sim.y;
}

TEST(ResidtraceCandidateSinusoid, FindsTheLineAndItsAmplitude) {
  const int N = 2000;
  const double w = 2 * kPi * 0.37, amp = 0.2;
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(N, amp, w, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(sinusoid_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.effect, "sinusoid");
  EXPECT_EQ(c.nadd, 2);
  const double bin = 2 * kPi / (N * kTs);
  const OutputTerm<double>& o = c.model.out.back();
  EXPECT_EQ(o.kind, OutputTermKind::kSinusoid);
  EXPECT_NEAR(o.omega, w, 0.1 * bin);
  const double a = std::hypot(o.c(0), o.c(1));
  const double sa = std::sqrt(o.cstd.squaredNorm() / 2);
  EXPECT_GT(sa, 0);
  EXPECT_NEAR(a, amp, 5 * sa + 0.02 * amp);
  // the model's own dynamics are kept
  EXPECT_NEAR(c.model.F(1), 2, 0.05);
  double g_p = -1;
  for (const EvidenceField<double>& f : c.evidence.fields) {
    if (f.name == "g_p") g_p = f.value(0);
  }
  EXPECT_GE(g_p, 0);
  EXPECT_LT(g_p, 1e-6);
  EXPECT_EQ(c.variant.substr(0, 4), "0.37") << c.variant;
  EXPECT_EQ(c.evidence.text.substr(0, 12), "line at 0.37") << c.evidence.text;
}

TEST(ResidtraceCandidateSinusoid, NotApplicableBranches) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(16, 0.2, 2 * kPi * 2, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(sinusoid_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "too few samples for a periodogram");
  // a validation record of 3 samples: a period of two cycles in it is
  // shorter than two samples
  record(400, 0.2, 2 * kPi * 2, &cur, &ctx);
  ctx.validation_samples = 3;
  ASSERT_TRUE(sinusoid_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason.substr(0, 41), "the records are too short for a sinusoid ")
      << c.reason;
}

TEST(ResidtraceCandidateSinusoid, BadInputIsAnError) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(200, 0.2, 2 * kPi * 2, &cur, &ctx);
  cur.estimate.e.resize(100);
  Candidate<double> c;
  EXPECT_FALSE(sinusoid_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(sinusoid_candidate<double>(first_order(), ctx, nullptr).ok());
}

}  // namespace
}  // namespace ctid::residtrace
