// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/recursive/convergence_detector.hpp on records
// built so that each index has a closed form: the output error's log mean
// square falls linearly then stays level (von Neumann's ratio of a linear
// trend is R = n (n + 1) / 6, of a level 0), the estimates jump once, and
// trace P / trace P0 falls as 1 / (1 + t).
#include "ctid/recursive/convergence_detector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ctid {
namespace {

const double* const kNoTrace = nullptr;  // no trace P / trace P0

// 30 blocks of 1 s, 10 samples each (t = k / 10, k = 0 .. 300).
struct Record {
  std::vector<double> t, y, y_hat, trace_ratio;
  Eigen::MatrixXd theta;
  Record() : theta(301, 2) {
    for (int k = 0; k <= 300; ++k) {
      const double tk = k / 10.0;
      const int b = k / 10;  // the block of sample k (block 30: t = 30 only)
      t.push_back(tk);
      y.push_back(1.0);
      // log E_b = -b up to block 11, then -11
      y_hat.push_back(1.0 - std::exp(-std::min(b, 11) / 2.0));
      theta(k, 0) = b <= 14 ? 2.0 : 1.0;
      theta(k, 1) = 0.0;
      trace_ratio.push_back(1 / (1 + tk));
    }
  }
};

ConvergenceSettings only(bool ey, bool th, bool p) {
  ConvergenceSettings s;
  s.block_length = 1;
  s.ey_floor = 0;
  s.use_output_error = ey;
  s.use_theta = th;
  s.use_p = p;
  return s;
}

TEST(ConvergenceDetector, NormalQuantile) {
  EXPECT_NEAR(normal_upper_quantile(0.05), 1.6448536269514722, 1e-14);
  EXPECT_NEAR(normal_upper_quantile(0.025), 1.959963984540054, 1e-14);
  EXPECT_NEAR(normal_upper_quantile(0.5), 0.0, 1e-15);
}

TEST(ConvergenceDetector, OutputErrorTrendThenLevel) {
  const Record r;
  ConvergenceReport<double> report;
  ASSERT_TRUE(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(),
                                 r.theta, r.trace_ratio.data(),
                                 only(true, false, false), report)
                  .ok());
  ASSERT_EQ(report.num_blocks, 30);
  const double n = 10;
  // R_crit = 2 / (2 - z sqrt(4 (n-2) / ((n+1) (n-1)))), z = 1.6449
  EXPECT_NEAR(report.r_crit,
              2 / (2 - 1.6448536269514722 *
                           std::sqrt(4 * (n - 2) / ((n + 1) * (n - 1)))),
              1e-13);
  EXPECT_TRUE(std::isnan(report.r(8)));               // fewer than n blocks
  EXPECT_NEAR(report.r(11), n * (n + 1) / 6, 1e-12);  // a linear trend
  // blocks 10 .. 19: nine at -11 and one at -10: s1 = 0.9, s2 = 1
  EXPECT_NEAR(report.r(19), 1.8, 1e-12);
  EXPECT_EQ(report.r(20), 0.0);  // level
  for (int b = 9; b < 30; ++b) {
    EXPECT_NEAR(std::log(report.ey_ms(b)), -std::min(b, 11), 1e-12) << b;
    EXPECT_EQ(report.steady_ey[b], b >= 19) << "block " << b;
  }
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.block, 19);
  EXPECT_DOUBLE_EQ(report.tsiv, 20.0);
  EXPECT_EQ(report.sample, 200);
}

TEST(ConvergenceDetector, OutputErrorBelowTheFloor) {
  const Record r;
  ConvergenceSettings s = only(true, false, false);
  s.ey_floor = std::exp(-5.5 / 2);  // E_b <= floor^2 Y_b from block 6 on
  ConvergenceReport<double> report;
  ASSERT_TRUE(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(),
                                 r.theta, kNoTrace, s, report)
                  .ok());
  EXPECT_EQ(report.block, 15);  // the window 6 .. 15
}

TEST(ConvergenceDetector, EstimatesJumpOnce) {
  const Record r;
  ConvergenceReport<double> report;
  ASSERT_TRUE(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(),
                                 r.theta, kNoTrace, only(false, true, false),
                                 report)
                  .ok());
  for (int b = 1; b < 30; ++b) {
    EXPECT_EQ(report.dtheta(b), b == 15 ? 1.0 : 0.0) << b;
  }
  for (int b = 9; b < 30; ++b) {
    // the window's changes dtheta(b-8 .. b) hold the jump for b = 15 .. 23
    const double expected = (b >= 15 && b <= 23) ? 1.0 / 3 : 0.0;
    EXPECT_NEAR(report.theta_index(b), expected, 1e-15) << b;
  }
  EXPECT_EQ(report.block, 9);
  // estimates that diverge count as an infinite change
  Record nan_record;
  nan_record.theta(55, 1) = NAN;
  ASSERT_TRUE(detect_convergence(nan_record.t.data(), nan_record.y.data(),
                                 nan_record.y_hat.data(), nan_record.theta,
                                 kNoTrace, only(false, true, false), report)
                  .ok());
  EXPECT_TRUE(std::isinf(report.dtheta(5)) && std::isinf(report.dtheta(6)));
  // windows with change 5 or 6 (b <= 14) or with the jump (15 .. 23) fail
  EXPECT_EQ(report.block, 24);
}

TEST(ConvergenceDetector, CovarianceIndexAndAllCriteria) {
  const Record r;
  ConvergenceReport<double> report;
  ConvergenceSettings s = only(false, false, true);
  s.p_tol = 0.05;
  ASSERT_TRUE(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(),
                                 r.theta, r.trace_ratio.data(), s, report)
                  .ok());
  for (int b = 0; b < 30; ++b) {
    EXPECT_DOUBLE_EQ(report.p_index(b), 1 / (1 + (b + 0.9))) << b;
  }
  // P_(b-9) <= 0.05 needs b - 9 + 1.9 >= 20
  EXPECT_EQ(report.block, 28);
  s.use_output_error = s.use_theta = true;
  ASSERT_TRUE(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(),
                                 r.theta, r.trace_ratio.data(), s, report)
                  .ok());
  EXPECT_EQ(report.block, 28);
  EXPECT_DOUBLE_EQ(report.tsiv, 29.0);
  s.p_tol = 0.01;  // never small enough
  ASSERT_TRUE(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(),
                                 r.theta, r.trace_ratio.data(), s, report)
                  .ok());
  EXPECT_FALSE(report.converged);
  EXPECT_TRUE(std::isnan(report.tsiv));
}

TEST(ConvergenceDetector, RejectsBadSettings) {
  const Record r;
  ConvergenceReport<double> report;
  ConvergenceSettings s = only(true, true, true);
  EXPECT_EQ(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(), r.theta,
                               kNoTrace, s, report)
                .code(),
            ErrorCode::kBadInput);  // P index without trace P
  s.use_p = false;
  s.block_length = 4;  // 7 blocks < nblocks
  EXPECT_EQ(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(), r.theta,
                               kNoTrace, s, report)
                .code(),
            ErrorCode::kBadInput);
  s.block_length = 1;
  s.alpha = 0.5;
  EXPECT_EQ(detect_convergence(r.t.data(), r.y.data(), r.y_hat.data(), r.theta,
                               kNoTrace, s, report)
                .code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
