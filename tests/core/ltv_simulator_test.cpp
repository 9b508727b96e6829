// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/simulation/ltv_simulator.hpp against analytic responses
// and an independently discretised closed loop.
#include "ctid/simulation/ltv_simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_util.hpp"

namespace ctid {
namespace {

ParameterTrajectory<double> constant(const Eigen::VectorXd& theta) {
  return [theta](double, Eigen::VectorXd& out) { out = theta; };
}

std::vector<double> simulate(const LtvSimulationConfig<double>& config,
                             const ParameterTrajectory<double>& trajectory,
                             const std::vector<double>& u, double ts,
                             Status* status = nullptr) {
  LtvSimulator<double> sim;
  Status s = sim.configure(config);
  std::vector<double> x(u.size(), NAN);
  if (s.ok()) {
    RecordView<double> record;
    record.u = u.data();
    record.num_samples = u.size();
    record.num_inputs = 1;
    record.ts = ts;
    SimulationOutputs<double> out;
    out.x = x.data();
    s = sim.simulate(trajectory, record, nullptr, nullptr, out);
  }
  if (status) *status = s;
  return x;
}

TEST(LtvSimulator, SecondOrderStepResponseIsExact) {
  const double wn = 2, zeta = 0.6, ts = 0.1;
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(2, 1, 0);
  const std::vector<double> u(300, 1.0);
  const auto x = simulate(
      config, constant(Eigen::Vector3d(2 * zeta * wn, wn * wn, wn * wn)), u,
      ts);
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  double worst = 0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double t = k * ts;
    const double exact =
        1 - std::exp(-zeta * wn * t) *
                (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t));
    worst = std::max(worst, std::abs(x[k] - exact));
  }
  EXPECT_LT(worst, 1e-13);
}

// (p + 3)/(p + 1) has a direct feedthrough: step response 3 - 2 exp(-t).
TEST(LtvSimulator, BiproperModelHasFeedthrough) {
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(1, 2, 0);
  const std::vector<double> u(100, 1.0);
  const auto x = simulate(config, constant(Eigen::Vector3d(1, 1, 3)), u, 0.05);
  for (std::size_t k = 0; k < u.size(); ++k) {
    ASSERT_NEAR(x[k], 3 - 2 * std::exp(-0.05 * k), 1e-13) << k;
  }
}

// x' + c/(t+1) x = b, x(0) = 0 has x = b (t+1)/(c+1) (1 - (t+1)^-(c+1)).
// The fourth-order Magnus step has a global error O(h^4): measured here at
// Ts = 0.1 (a1 halves within the first second) and with 2 and 4 sub-steps.
TEST(LtvSimulator, FirstOrderLtvMatchesAnalyticSolutionToFourthOrder) {
  const double c = 2, b = 3, ts = 0.1;
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(1, 1, 0);
  ParameterTrajectory<double> trajectory = [&](double t, Eigen::VectorXd& th) {
    th.resize(2);
    th << c / (t + 1), b;
  };
  const std::vector<double> u(101, 1.0);
  std::vector<double> errors;
  for (int substeps : {1, 2, 4}) {
    config.substeps = substeps;
    const auto x = simulate(config, trajectory, u, ts);
    double worst = 0;
    for (std::size_t k = 0; k < u.size(); ++k) {
      const double t = k * ts;
      const double exact =
          b * (t + 1) / (c + 1) * (1 - std::pow(t + 1, -(c + 1)));
      worst = std::max(worst, std::abs(x[k] - exact));
    }
    errors.push_back(worst);
  }
  RecordProperty("error_1_substep", test::scientific(errors[0]));
  RecordProperty("error_2_substeps", test::scientific(errors[1]));
  RecordProperty("error_4_substeps", test::scientific(errors[2]));
  EXPECT_LT(errors[0], 1e-6) << "one Magnus step per sample";
  EXPECT_GT(errors[0] / errors[1], 12.0) << "order below 3.6";
  EXPECT_GT(errors[1] / errors[2], 12.0) << "order below 3.6";
}

// Ramp input t with FOH through p x = 2 u: x = t^2 exactly.
TEST(LtvSimulator, FirstOrderHoldIntegratesLinearInputExactly) {
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(1, 1, 0);
  config.u_intersample = InterSample::kFoh;
  std::vector<double> u(50);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = 0.2 * k;
  const auto x = simulate(config, constant(Eigen::Vector2d(0, 2)), u, 0.2);
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double t = 0.2 * k;
    ASSERT_NEAR(x[k], t * t, 1e-12) << k;
  }
}

TEST(LtvSimulator, InputDelayShiftsTheOutput) {
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(2, 2, 0);
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  std::vector<double> u(200);
  for (auto& v : u) v = normal(rng);
  const Eigen::Vector4d theta(1.5, 2.0, 0.5, 1.0);
  const auto x0 = simulate(config, constant(theta), u, 0.1);
  config.orders = siso_orders(2, 2, 3);
  const auto x3 = simulate(config, constant(theta), u, 0.1);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(x3[k], 0.0);
  for (std::size_t k = 3; k < u.size(); ++k) {
    ASSERT_NEAR(x3[k], x0[k - 3], 1e-12) << k;
  }
}

// Plant b/(p + a) under the PI controller C = kp + ki Ts/(1 - q^-1),
// compared with the same loop built from the analytic ZOH discretisation
// x(k+1) = e^(-a Ts) x(k) + b/a (1 - e^(-a Ts)) u(k).
TEST(LtvSimulator, ClosedLoopMatchesIndependentDiscretisation) {
  const double a = 1.5, b = 2.0, ts = 0.05, kp = 0.8, ki = 1.2;
  for (int nk : {0, 2}) {
    LtvSimulationConfig<double> config;
    config.orders = siso_orders(1, 1, nk);
    config.closed_loop = true;
    config.controller = pid_backward_euler(kp, ki, 0.0, ts);
    const int n = 400;
    std::vector<double> r1(n), r2(n), noise(n), x(n), u(n);
    std::mt19937 rng(9);
    std::normal_distribution<double> normal;
    for (int k = 0; k < n; ++k) {
      r1[k] = 0.1 * std::sin(0.05 * k);
      r2[k] = (k / 100) % 2 ? 1.0 : -1.0;
      noise[k] = 0.01 * normal(rng);
    }
    LtvSimulator<double> sim;
    ASSERT_TRUE(sim.configure(config).ok());
    RecordView<double> record;
    record.u = r1.data();
    record.num_samples = n;
    record.num_inputs = 1;
    record.ts = ts;
    SimulationOutputs<double> out;
    out.x = x.data();
    out.u_applied = u.data();
    ASSERT_TRUE(sim.simulate(constant(Eigen::Vector2d(a, b)), record, r2.data(),
                             noise.data(), out)
                    .ok());
    const double phi = std::exp(-a * ts), gamma = b / a * (1 - phi);
    double state = 0, integral = 0;
    std::vector<double> u_ref(n);
    for (int k = 0; k < n; ++k) {
      const double plant_input = k >= nk ? u_ref[k - nk] : 0.0;
      if (k > 0) {
        const double prev_input = k - 1 >= nk ? u_ref[k - 1 - nk] : 0.0;
        state = phi * state + gamma * prev_input;
      }
      (void)plant_input;
      const double e = r2[k] - state - noise[k];
      integral += ki * ts * e;
      u_ref[k] = r1[k] + kp * e + integral;
      ASSERT_NEAR(x[k], state, 1e-12) << "nk " << nk << " k " << k;
      ASSERT_NEAR(u[k], u_ref[k], 1e-12) << "nk " << nk << " k " << k;
    }
  }
}

TEST(LtvSimulator, NoiseScaleGivesRequestedSnr) {
  std::vector<double> x(1000);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::sin(0.1 * k);
  const double scale = noise_scale_for_snr(x.data(), x.size(), 10.0);
  double power = 0;
  for (double v : x) power += v * v;
  power /= x.size();
  EXPECT_NEAR(10 * std::log10(power / (scale * scale)), 10.0, 1e-12);
}

TEST(LtvSimulator, RejectsBadConfigurations) {
  LtvSimulator<double> sim;
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(2, 4, 0);
  EXPECT_EQ(sim.configure(config).code(), ErrorCode::kBadInput);
  config.orders = siso_orders(2, 1, 0);
  config.substeps = 0;
  EXPECT_EQ(sim.configure(config).code(), ErrorCode::kBadInput);
  config.substeps = 1;
  config.closed_loop = true;
  EXPECT_EQ(sim.configure(config).code(), ErrorCode::kBadInput)
      << "closed loop without a controller";
  config.controller = pid_backward_euler(1.0, 0.0, 0.0, 0.1);
  config.u_intersample = InterSample::kFoh;
  EXPECT_EQ(sim.configure(config).code(), ErrorCode::kBadInput);
  config.u_intersample = InterSample::kZoh;
  config.initial_state = Eigen::VectorXd::Zero(3);
  EXPECT_EQ(sim.configure(config).code(), ErrorCode::kDimensionMismatch);
}

TEST(LtvSimulator, UnstableSystemIsReportedNotReturned) {
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(1, 1, 0);
  const std::vector<double> u(2000, 1.0);
  Status status;
  simulate(config, constant(Eigen::Vector2d(-500, 1)), u, 0.1, &status);
  EXPECT_EQ(status.code(), ErrorCode::kNumericalFailure) << status.message();
}

TEST(LtvSimulator, NonFiniteTrajectoryIsBadInput) {
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(1, 1, 0);
  const std::vector<double> u(10, 1.0);
  Status status;
  simulate(config, constant(Eigen::Vector2d(NAN, 1)), u, 0.1, &status);
  EXPECT_EQ(status.code(), ErrorCode::kBadInput);
}

Eigen::VectorXd conv(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd c = Eigen::VectorXd::Zero(a.size() + b.size() - 1);
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    for (Eigen::Index j = 0; j < b.size(); ++j) c(i + j) += a(i) * b(j);
  }
  return c;
}

// A sixth-order lightly damped structure, modes at 3.5, 16 and 38 Hz
// (22-239 rad/s, damping 0.05, 0.02, 0.01), numerator of degree 5: the
// companion form has coefficients from 1 to 2.8e11, and its unbalanced
// exponential made the simulation overflow within 0.7 s (Ts = 2 ms). The
// reference is independent of the simulator: the sum of the three modes
// (m_i w_i p + k_i w_i^2) / (p^2 + 2 z_i w_i p + w_i^2), each simulated
// exactly through its own well-scaled 2-by-2 exponential (test_util's
// simulate_zoh). Agreement to 1e-9 of the output's norm (measured about
// 2e-13; the modal sum rounds at 1e-16 relative to each mode, whose
// responses are up to 10 times the total).
TEST(LtvSimulator, SixthOrderWithSpreadModesMatchesTheSumOfItsModes) {
  const double pi = std::acos(-1.0);
  const double w[] = {2 * pi * 3.5, 2 * pi * 16, 2 * pi * 38};
  const double z[] = {0.05, 0.02, 0.01};
  const double gain[] = {1, -0.6, 0.3};
  const double slope[] = {0.02, 0.01, -0.005};
  Eigen::VectorXd den = Eigen::VectorXd::Ones(1);
  Eigen::VectorXd num = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd mode_den[3], mode_num[3];
  for (int i = 0; i < 3; ++i) {
    mode_den[i] = Eigen::Vector3d(1, 2 * z[i] * w[i], w[i] * w[i]);
    mode_num[i] = Eigen::Vector2d(slope[i] * w[i], gain[i] * w[i] * w[i]);
    den = conv(den, mode_den[i]);
  }
  for (int i = 0; i < 3; ++i) {
    Eigen::VectorXd part = mode_num[i];
    for (int j = 0; j < 3; ++j) {
      if (j != i) part = conv(part, mode_den[j]);
    }
    num += part;
  }
  ASSERT_GT(den(6), 1e11);
  LtvSimulationConfig<double> config;
  config.orders = siso_orders(6, 6, 0);
  Eigen::VectorXd theta(12);
  theta << den.tail(6), num;
  const std::vector<double> u = test::binary_input(20000, 10, 7);
  for (const double ts : {1.0 / 500, 1.0 / 5000}) {
    Status status;
    const auto x = simulate(config, constant(theta), u, ts, &status);
    ASSERT_TRUE(status.ok()) << status.message();
    Eigen::VectorXd reference = Eigen::VectorXd::Zero(u.size());
    for (int i = 0; i < 3; ++i) {
      const auto y = test::simulate_zoh(mode_num[i], mode_den[i], u, ts);
      reference += Eigen::Map<const Eigen::VectorXd>(y.data(), y.size());
    }
    const double error = test::relative_error(
        Eigen::Map<const Eigen::VectorXd>(x.data(), x.size()), reference);
    EXPECT_LT(error, 1e-9) << "Ts " << ts << ": relative error "
                           << test::scientific(error);
  }
}

TEST(PiecewiseLinearTrajectory, InterpolatesBetweenSamples) {
  const double t[] = {0.0, 1.0, 3.0};
  const double thetas[] = {1.0, 3.0, 7.0, 10.0, 20.0, 40.0};  // 3-by-2
  const auto traj = piecewise_linear_trajectory<double>(t, thetas, 3, 2);
  Eigen::VectorXd th;
  traj(0.5, th);
  EXPECT_TRUE(test::MatrixNear(th, Eigen::Vector2d(2, 15), 1e-15));
  traj(2.0, th);
  EXPECT_TRUE(test::MatrixNear(th, Eigen::Vector2d(5, 30), 1e-15));
  traj(5.0, th);
  EXPECT_TRUE(test::MatrixNear(th, Eigen::Vector2d(7, 40), 1e-15));
}

}  // namespace
}  // namespace ctid
