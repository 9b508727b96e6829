// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/simulation/controller.hpp: the backward-Euler PID against
// its definition, run sample by sample.
#include "ctid/simulation/controller.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ctid {
namespace {

TEST(Controller, BackwardEulerPidMatchesItsDefinition) {
  const double kp = 0.7, ki = 2.0, kd = 0.1, ts = 0.05;
  DiscreteFilter<double> c;
  c.configure(pid_backward_euler(kp, ki, kd, ts));
  double integral = 0, e_prev = 0;
  for (int k = 0; k < 200; ++k) {
    const double e = std::sin(0.1 * k) + 0.3 * std::cos(0.7 * k);
    integral += ki * ts * e;
    const double v = kp * e + integral + kd / ts * (e - e_prev);
    e_prev = e;
    ASSERT_NEAR(c.step(e), v, 1e-11) << k;
  }
}

TEST(Controller, FreeResponsePlusFeedthroughIsTheOutput) {
  DiscreteTransferFunction<double> tf;
  tf.numerator = Eigen::Vector3d(2.0, 0.5, -0.3);
  tf.denominator = Eigen::Vector2d(2.0, -1.0);  // normalised to 1 - 0.5 q^-1
  DiscreteFilter<double> c;
  c.configure(tf);
  double y1 = 0, e1 = 0, e2 = 0;
  for (int k = 0; k < 50; ++k) {
    const double e = 1.0 / (k + 1);
    const double predicted = c.feedthrough() * e + c.free_response();
    const double v = c.step(e);
    const double direct = 0.5 * y1 + (2.0 * e + 0.5 * e1 - 0.3 * e2) / 2.0;
    EXPECT_NEAR(v, predicted, 1e-14);
    ASSERT_NEAR(v, direct, 1e-14) << k;
    y1 = v;
    e2 = e1;
    e1 = e;
  }
}

TEST(Controller, Validation) {
  DiscreteTransferFunction<double> tf;
  EXPECT_FALSE(validate_controller(tf).ok());
  tf.numerator = Eigen::VectorXd::Ones(1);
  tf.denominator = Eigen::VectorXd::Zero(2);
  EXPECT_FALSE(validate_controller(tf).ok()) << "zero leading coefficient";
  tf.denominator(0) = 1;
  EXPECT_TRUE(validate_controller(tf).ok());
  tf.numerator(0) = NAN;
  EXPECT_FALSE(validate_controller(tf).ok());
}

}  // namespace
}  // namespace ctid
