// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/pole_determination.hpp: the standard
// error of a real pole against a numerical Jacobian of the roots (an
// independent computation of the same first-order propagation), the
// |p| h > 1000 bound, several denominators (bound only), the median
// interval of an irregular record, and the status refined_iv() reports for
// first-order data fitted with one pole too many.
#include "ctid/offline/pole_determination.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ctid/offline/refined_iv.hpp"

namespace ctid {
namespace {

RivProblem<double> one_group(int nf, int nb) {
  RivProblem<double> p;
  p.nf = {nf};
  RivChannel c;
  c.nb = nb;
  p.channels = {c};
  return p;
}

// The real root of p^2 + f1 p + f2 nearest to `near`.
double root_near(double f1, double f2, double near) {
  const double d = std::sqrt(f1 * f1 - 4 * f2);
  const double a = (-f1 + d) / 2, b = (-f1 - d) / 2;
  return std::abs(a - near) < std::abs(b - near) ? a : b;
}

TEST(PoleDetermination, StandardErrorMatchesNumericalJacobian) {
  // F = (p + 1)(p + 3); a covariance that puts the pole at -1 at the edge
  const double f1 = 4, f2 = 3;
  Eigen::Matrix2d P;
  P << 0.30, 0.12, 0.12, 0.20;
  const double h = 1e-6, r = -1;
  Eigen::RowVector2d J;
  J(0) = (root_near(f1 + h, f2, r) - root_near(f1 - h, f2, r)) / (2 * h);
  J(1) = (root_near(f1, f2 + h, r) - root_near(f1, f2 - h, r)) / (2 * h);
  const double sd = std::sqrt((J * P * J.transpose())(0, 0));
  Vector<double> theta(3);
  theta << f1, f2, 1.0;
  Matrix<double> cov = Matrix<double>::Zero(3, 3);
  // scaled so that sd(p = -1) is just above, then just below, |p| = 1
  cov.topLeftCorner(2, 2) = P * std::pow(1.01 / sd, 2);
  const std::string above =
      undetermined_pole(one_group(2, 1), theta, cov, 0.01);
  EXPECT_NE(above.find("p = -1 has a standard error of 1.01"),
            std::string::npos)
      << above;
  cov.topLeftCorner(2, 2) = P * std::pow(0.99 / sd, 2);
  EXPECT_EQ(undetermined_pole(one_group(2, 1), theta, cov, 0.01), "");
}

TEST(PoleDetermination, PoleBeyondTheSamplesIsNamed) {
  // F = (p + 1)(p + 2e5): with Ts = 0.01, |p| Ts = 2000 > 1000
  Vector<double> theta(3);
  theta << 1 + 2e5, 2e5, 1.0;
  const Matrix<double> cov = Matrix<double>::Zero(3, 3);
  const std::string why = undetermined_pole(one_group(2, 1), theta, cov, 0.01);
  EXPECT_NE(why.find("|p| Ts = 2e+03 > 1000"), std::string::npos) << why;
  // the same pole with Ts = 1e-3: |p| Ts = 200, seen by the samples
  EXPECT_EQ(undetermined_pole(one_group(2, 1), theta, cov, 1e-3), "");
}

TEST(PoleDetermination, ComplexPolesAndIntegratorsAreNotJudged) {
  Vector<double> theta(4);
  theta << 1.0, 4.0, 0.0, 1.0;  // F = p (p^2 + p + 4)
  const Matrix<double> cov = Matrix<double>::Identity(4, 4) * 1e6;
  EXPECT_EQ(undetermined_pole(one_group(3, 1), theta, cov, 0.01), "");
}

TEST(PoleDetermination, SeveralDenominatorsUseTheBoundOnly) {
  RivProblem<double> p;
  p.nf = {1, 1};
  RivChannel a, b;
  a.group = 0;
  b.group = 1;
  p.channels = {a, b};
  Vector<double> theta(4);
  theta << 0.5, 3.0, 1.0, 1.0;
  // a huge covariance: no standard-error judgement with two groups
  const Matrix<double> cov = Matrix<double>::Identity(4, 4) * 1e6;
  EXPECT_EQ(undetermined_pole(p, theta, cov, 0.01), "");
  theta(1) = 2e6;  // the second group's pole at -2e6: |p| Ts = 2e4
  EXPECT_NE(undetermined_pole(p, theta, cov, 0.01).find("p = -2e+06"),
            std::string::npos);
}

TEST(PoleDetermination, TypicalIntervalIsTheMedianStep) {
  const std::vector<double> t = {0.0, 0.1, 0.3, 0.4, 1.0};  // 0.1 .2 .1 .6
  RivData<double> data;
  data.instants = t.data();
  data.num_samples = 5;
  EXPECT_DOUBLE_EQ(typical_interval(data), 0.15);
  data.num_samples = 4;  // steps 0.1 0.2 0.1
  EXPECT_DOUBLE_EQ(typical_interval(data), 0.1);
  RivData<double> uniform;
  uniform.ts = 0.05;
  uniform.num_samples = 10;
  EXPECT_DOUBLE_EQ(typical_interval(uniform), 0.05);
}

TEST(PoleDetermination, SrivcStatusSaysOverParameterised) {
  // first-order data y = 2 / (p + 0.5) u fitted with [nb nf] = [1 2]:
  // the extra pole is not determined (it runs off or keeps a standard
  // error above its magnitude), and the fit's status says so; a
  // second-order system fitted so is determined. (The standard-error
  // rule is a one-sigma rule: on some noise draws the extra pole's error
  // falls below its magnitude and the fit passes as determined.)
  const double ts = 0.05;
  const int N = 2000;
  std::vector<double> u(N), y1(N), y2(N);
  unsigned state = 12345;
  double level = 1;
  for (int k = 0; k < N; ++k) {
    if (k % 4 == 0) {
      state = state * 1103515245u + 12345u;
      level = (state >> 16) & 1 ? 1.0 : -1.0;
    }
    u[k] = level;
  }
  // exact ZOH of 2 / (p + 0.5) and of 4 / (p^2 + 1.2 p + 4) by fine Euler
  // steps (1000 per sample), plus a small deterministic disturbance
  std::mt19937 noise(1);
  std::normal_distribution<double> normal;
  double x = 0, z1 = 0, z2 = 0;
  for (int k = 0; k < N; ++k) {
    y1[k] = x + 0.02 * normal(noise);
    y2[k] = z1 + 0.05 * normal(noise);
    for (int i = 0; i < 1000; ++i) {
      const double dt = ts / 1000;
      x += dt * (-0.5 * x + 2 * u[k]);
      const double a = z2, b = -1.2 * z2 - 4 * z1 + 4 * u[k];
      z1 += dt * a;
      z2 += dt * b;
    }
  }
  RivSettings<double> settings;
  settings.method = RivMethod::kSrivc;
  for (int which = 0; which < 2; ++which) {
    const std::vector<double>& y = which == 0 ? y1 : y2;
    RivData<double> data;
    data.y = y.data();
    data.w = u.data();
    data.num_samples = N;
    data.ts = ts;
    RivResult<double> result;
    const Status s = refined_iv(one_group(2, 1), settings, data, &result);
    ASSERT_TRUE(s.ok()) << s.message();
    ASSERT_TRUE(result.converged);
    if (which == 0) {
      // the rule's verdict on the fit is the fit's status, in its reason
      const std::string why = undetermined_pole(one_group(2, 1), result.theta,
                                                result.covariance, ts);
      EXPECT_FALSE(why.empty()) << result.theta.transpose();
      EXPECT_FALSE(result.determined) << result.reason;
      EXPECT_NE(result.reason.find(why), std::string::npos) << result.reason;
    } else {
      EXPECT_TRUE(result.determined) << result.reason;
      EXPECT_EQ(result.reason.find("standard error of"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace ctid
