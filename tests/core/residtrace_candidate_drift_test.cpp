// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_drift.hpp (the
// segment test of the drift candidate):
//   - a first-order system b(t) / (p + 2) whose gain rises linearly from
//     3 to 4.5 along the record (simulated here sample by sample with the
//     exact zero-order-hold step, not by the core): the segments disagree
//     (p far below alpha), the segment estimates of b follow b(t) at the
//     segments' middles and the trend of b is the true slope with a large
//     t value, that of a small;
//   - the same system with a constant gain: the segments agree, with the
//     test's figures in the reason;
//   - too short a record and a physical realisation give their reasons;
//     an inconsistent model is a Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_drift.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;
constexpr double kA = 2;

ResidtraceModel<double> first_order() {
  ResidtraceModel<double> m;
  m.F = Eigen::Vector2d(1, kA);
  m.fixed = {false};
  StructureChannel<double> c;
  c.col = 0;
  c.nb = 1;
  c.B = Eigen::VectorXd::Constant(1, 3);
  m.channels.push_back(c);
  return m;
}

double gain(int k, int N, double rise) { return 3 * (1 + rise * k / N); }

// y' = -a y + b(t) u with u and b held over each sample: the exact step.
// The model is then fitted on the whole record (a frozen model).
void record(int N, double rise, ResidtraceModel<double>* cur,
            CandidateContext<double>* ctx) {
  const std::vector<double> u = test::binary_input(N, 7, 5);
  ctx->D.u = Eigen::Map<const Eigen::VectorXd>(u.data(), N);
  ctx->D.ts = kTs;
  ctx->D.y.resize(N);
  std::mt19937 gen(6);
  std::normal_distribution<double> noise(0.0, 0.01);
  const double phi = std::exp(-kA * kTs);
  double x = 0;
  for (int k = 0; k < N; ++k) {
    ctx->D.y(k) = x + noise(gen);
    x = phi * x + gain(k, N, rise) / kA * (1 - phi) * u[k];
  }
  ctx->fit.max_iterations = 20;
  ASSERT_TRUE(
      fit_model<double>(first_order(), ctx->D, {first_order().F}, ctx->fit, cur)
          .ok());
  ASSERT_TRUE(cur->estimate.ok);
}

TEST(ResidtraceCandidateDrift, SegmentsFollowADriftingGain) {
  const int N = 2400;
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(N, 0.5, &cur, &ctx);
  DriftSegments<double> r;
  ASSERT_TRUE(drift_segments<double>(cur, ctx, 0.01, &r).ok());
  EXPECT_TRUE(r.reason.empty()) << r.reason;
  EXPECT_EQ(r.K, 8);
  EXPECT_EQ(r.L, N / 8);
  ASSERT_EQ(r.segments, 8);
  EXPECT_EQ(r.dof, 7 * 2);
  EXPECT_LT(r.p, 1e-6);
  for (int k = 0; k < r.segments; ++k) {
    const double kmid = (k + 0.5) * r.L;
    EXPECT_NEAR(r.tmid(k), kmid * kTs, 1e-12);
    // the segment's estimate of b is b(t) at its middle (b is linear)
    EXPECT_NEAR(r.theta(k, 1), gain(static_cast<int>(kmid), N, 0.5), 0.03)
        << "segment " << k;
    EXPECT_NEAR(r.theta(k, 0), kA, 0.03) << "segment " << k;
  }
  const double slope = 3 * 0.5 / (N * kTs);  // db/dt
  EXPECT_NEAR(r.slope(1), slope, 0.05 * slope);
  EXPECT_GT(std::abs(r.tval(1)), 20);
  EXPECT_LT(std::abs(r.slope(0)), 0.1 * slope);
  ASSERT_EQ(r.shape.size(), 2);
  EXPECT_GT(r.shape(1), r.shape(0));  // the gain is what drifts
  EXPECT_GT(r.shape(0), 0);
}

TEST(ResidtraceCandidateDrift, ConstantParametersAgree) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(2400, 0, &cur, &ctx);
  DriftSegments<double> r;
  ASSERT_TRUE(drift_segments<double>(cur, ctx, 0.01, &r).ok());
  EXPECT_GE(r.p, 0.01);
  EXPECT_FALSE(r.failed);
  EXPECT_EQ(r.reason.substr(0, 37), "the segment fits agree (K = 8: chi^2 ")
      << r.reason;
  EXPECT_NE(r.reason.find("on 14 dof"), std::string::npos) << r.reason;
}

TEST(ResidtraceCandidateDrift, NotApplicable) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(2400, 0, &cur, &ctx);
  DriftSegments<double> r;
  CandidateContext<double> shortened = ctx;
  shortened.D.y = ctx.D.y.head(200);
  shortened.D.u = ctx.D.u.topRows(200);
  ASSERT_TRUE(drift_segments<double>(cur, shortened, 0.01, &r).ok());
  EXPECT_EQ(r.reason,
            "200 samples are too few for segment fits of 2 "
            "parameters");
  ResidtraceModel<double> phys = cur;
  phys.has_phys = true;
  ASSERT_TRUE(drift_segments<double>(phys, ctx, 0.01, &r).ok());
  EXPECT_EQ(r.reason,
            "a physical realisation (end stop, cascade) is not "
            "tracked");
}

TEST(ResidtraceCandidateDrift, BadInput) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(1200, 0, &cur, &ctx);
  DriftSegments<double> r;
  EXPECT_FALSE(drift_segments<double>(cur, ctx, 0.01, nullptr).ok());
  ResidtraceModel<double> bad = cur;
  bad.estimate.cov = Eigen::MatrixXd::Identity(3, 3);
  EXPECT_FALSE(drift_segments<double>(bad, ctx, 0.01, &r).ok());
  CandidateContext<double> c2 = ctx;
  c2.D.u = ctx.D.u.topRows(100);
  EXPECT_FALSE(drift_segments<double>(cur, c2, 0.01, &r).ok());
}

}  // namespace
}  // namespace ctid::residtrace
