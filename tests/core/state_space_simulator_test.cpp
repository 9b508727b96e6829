// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/simulation/state_space_simulator.hpp against
// independent computations: a discretisation through the eigenvalues of A
// (no matrix exponential of an augmented matrix), analytic responses of a
// first-order lag to a delayed step and a delayed ramp, and the invariance
// of the input-output map under a badly scaled state similarity.
#include "ctid/simulation/state_space_simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "test_util.hpp"

namespace ctid {
namespace {

using test::MatrixNear;

RecordView<double> uniform(const Eigen::MatrixXd& u, double ts) {
  RecordView<double> record;
  record.u = u.data();
  record.num_samples = u.rows();
  record.num_inputs = u.cols();
  record.ts = ts;
  return record;
}

// Two states with complex modes, two inputs, two outputs, D != 0.
StateSpaceModel<double> mimo() {
  StateSpaceModel<double> m;
  m.a.resize(2, 2);
  m.a << -1, 2, -2, -1;
  m.b.resize(2, 2);
  m.b << 0, 1, 1, 0.5;
  m.c.resize(2, 2);
  m.c << 1, 0, 0.3, 1;
  m.d.resize(2, 2);
  m.d << 0.5, 0, 0, -0.2;
  return m;
}

// x(t+h) = Phi x + G0 u_k + G1 s for u(t_k + tau) = u_k + s tau, with Phi =
// V exp(Lambda h) V^-1, G0 = A^-1 (Phi - I) B, G1 = A^-2 (Phi - I - A h) B
// (A invertible): the closed-form integrals, no augmented exponential.
struct EigenHold {
  Eigen::MatrixXd phi, g0, g1;
  EigenHold(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double h) {
    Eigen::EigenSolver<Eigen::MatrixXd> es(a);
    const Eigen::MatrixXcd v = es.eigenvectors();
    Eigen::VectorXcd e = es.eigenvalues();
    for (Eigen::Index i = 0; i < e.size(); ++i) e(i) = std::exp(e(i) * h);
    phi = (v * e.asDiagonal() * v.inverse()).real();
    const Eigen::MatrixXd ai = a.inverse();
    const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(a.rows(), a.cols());
    g0 = ai * (phi - id) * b;
    g1 = ai * ai * (phi - id - a * h) * b;
  }
};

// The reference simulation for integer delays nk (ny-by-nu), with the hold
// of each interval h_k from `steps`.
Eigen::MatrixXd reference(const StateSpaceModel<double>& m,
                          const Eigen::MatrixXd& u,
                          const std::vector<double>& steps, bool foh,
                          const Eigen::MatrixXi& nk) {
  const Eigen::Index n = u.rows();
  Eigen::MatrixXd y(n, m.c.rows());
  for (Eigen::Index i = 0; i < m.c.rows(); ++i) {
    Eigen::MatrixXd v = Eigen::MatrixXd::Zero(n, u.cols());
    for (Eigen::Index j = 0; j < u.cols(); ++j) {
      for (Eigen::Index k = nk(i, j); k < n; ++k) v(k, j) = u(k - nk(i, j), j);
    }
    Eigen::VectorXd x = Eigen::VectorXd::Zero(m.a.rows());
    for (Eigen::Index k = 0; k < n; ++k) {
      y(k, i) = m.c.row(i).dot(x) + m.d.row(i).dot(v.row(k));
      if (k + 1 == n) break;
      const EigenHold hold(m.a, m.b, steps[k]);
      Eigen::VectorXd slope = Eigen::VectorXd::Zero(u.cols());
      if (foh) slope = (v.row(k + 1) - v.row(k)).transpose() / steps[k];
      x = hold.phi * x + hold.g0 * v.row(k).transpose() + hold.g1 * slope;
    }
  }
  return y;
}

Eigen::MatrixXd binary_inputs(int n) {
  const std::vector<double> u1 = test::binary_input(n, 3, 11);
  const std::vector<double> u2 = test::binary_input(n, 5, 12);
  Eigen::MatrixXd u(n, 2);
  for (int k = 0; k < n; ++k) {
    u(k, 0) = u1[k];
    u(k, 1) = u2[k] + 0.1 * k / n;
  }
  return u;
}

// Tolerance: a few hundred steps of a contracting propagator, each exact to
// about 1e-15 relative; the reference's eigenvector inverse adds its own
// rounding (condition number of V about 1 here).
constexpr double kTol = 1e-12;

TEST(StateSpaceSimulator, ZohAndFohMatchTheClosedFormHold) {
  const StateSpaceModel<double> m = mimo();
  const Eigen::MatrixXd u = binary_inputs(200);
  const double ts = 0.1;
  const std::vector<double> steps(u.rows(), ts);
  for (bool foh : {false, true}) {
    Eigen::MatrixXd y;
    const Status s = simulate_state_space(
        m, foh ? InterSample::kFoh : InterSample::kZoh, uniform(u, ts), y);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_TRUE(MatrixNear(
        y, reference(m, u, steps, foh, Eigen::MatrixXi::Zero(2, 2)), kTol))
        << (foh ? "foh" : "zoh");
  }
}

TEST(StateSpaceSimulator, IntegerDelaysPerOutputAndInput) {
  StateSpaceModel<double> m = mimo();
  Eigen::MatrixXi nk(2, 2);
  nk << 0, 3, 2, 7;
  m.delays = nk.cast<double>();
  const Eigen::MatrixXd u = binary_inputs(150);
  const double ts = 0.05;
  const std::vector<double> steps(u.rows(), ts);
  for (bool foh : {false, true}) {
    Eigen::MatrixXd y;
    ASSERT_TRUE(
        simulate_state_space(m, foh ? InterSample::kFoh : InterSample::kZoh,
                             uniform(u, ts), y)
            .ok());
    EXPECT_TRUE(MatrixNear(y, reference(m, u, steps, foh, nk), kTol));
  }
}

TEST(StateSpaceSimulator, IrregularInstants) {
  const StateSpaceModel<double> m = mimo();
  const Eigen::MatrixXd u = binary_inputs(120);
  std::vector<double> t(u.rows());
  std::vector<double> steps(u.rows());
  t[0] = 0.3;
  for (Eigen::Index k = 0; k + 1 < u.rows(); ++k) {
    steps[k] = 0.05 + 0.1 * ((k * 7) % 5) / 4.0;  // 0.05 .. 0.15
    t[k + 1] = t[k] + steps[k];
  }
  RecordView<double> record = uniform(u, 0);
  record.instants = t.data();
  for (bool foh : {false, true}) {
    Eigen::MatrixXd y;
    const Status s = simulate_state_space(
        m, foh ? InterSample::kFoh : InterSample::kZoh, record, y);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_TRUE(MatrixNear(
        y, reference(m, u, steps, foh, Eigen::MatrixXi::Zero(2, 2)), kTol));
  }
}

// x' = -a x + b v, y = x + d v, v(t) = u(t - tau Ts); the input starts at
// t = 0 (zero before). A step: v = 1 for t >= tau Ts; a ramp u(t) = t
// (FOH through the samples u_k = k Ts, which starts from the zero before
// the record with slope 1 as well): v = max(t - tau Ts, 0).
StateSpaceModel<double> lag(double a, double b, double d, double tau) {
  StateSpaceModel<double> m;
  m.a = Eigen::MatrixXd::Constant(1, 1, -a);
  m.b = Eigen::MatrixXd::Constant(1, 1, b);
  m.c = Eigen::MatrixXd::Constant(1, 1, 1.0);
  m.d = Eigen::MatrixXd::Constant(1, 1, d);
  m.delays = Eigen::MatrixXd::Constant(1, 1, tau);
  return m;
}

TEST(StateSpaceSimulator, FractionalDelayStepIsAnalytic) {
  const double a = 2, b = 3, d = 0.4, ts = 0.1;
  const int n = 60;
  const Eigen::MatrixXd u = Eigen::MatrixXd::Ones(n, 1);
  for (double tau : {0.3, 2.5, 4.75}) {
    Eigen::MatrixXd y;
    const Status s = simulate_state_space(lag(a, b, d, tau), InterSample::kZoh,
                                          uniform(u, ts), y);
    ASSERT_TRUE(s.ok()) << s.message();
    Eigen::VectorXd exact(n);
    for (int k = 0; k < n; ++k) {
      const double r = k * ts - tau * ts;  // time since the delayed step
      // at t_k the delayed step has arrived only when r > 0 (tau is not an
      // integer, so r != 0)
      exact(k) = r > 0 ? b / a * (1 - std::exp(-a * r)) + d : 0.0;
    }
    EXPECT_TRUE(MatrixNear(y.col(0), exact, 1e-13)) << "tau " << tau;
  }
}

TEST(StateSpaceSimulator, FractionalDelayRampIsAnalytic) {
  const double a = 1.5, b = 2, d = -0.3, ts = 0.2;
  const int n = 50;
  Eigen::MatrixXd u(n, 1);
  for (int k = 0; k < n; ++k) u(k) = k * ts;
  for (double tau : {0.5, 1.25, 3.9}) {
    Eigen::MatrixXd y;
    ASSERT_TRUE(simulate_state_space(lag(a, b, d, tau), InterSample::kFoh,
                                     uniform(u, ts), y)
                    .ok());
    Eigen::VectorXd exact(n);
    for (int k = 0; k < n; ++k) {
      const double r = std::max(k * ts - tau * ts, 0.0);
      exact(k) = b * (r / a - (1 - std::exp(-a * r)) / (a * a)) + d * r;
    }
    EXPECT_TRUE(MatrixNear(y.col(0), exact, 1e-13)) << "tau " << tau;
  }
}

// Fractional and integer delays in one model, D != 0: each output is the
// sum of the single-pair responses, and the integer pair's feedthrough
// reads the input at the sample itself.
TEST(StateSpaceSimulator, MixedDelaysAddUpPairByPair) {
  StateSpaceModel<double> m = mimo();
  m.delays.resize(2, 2);
  m.delays << 0, 1.5, 2.25, 3;
  const Eigen::MatrixXd u = binary_inputs(100);
  const double ts = 0.1;
  for (InterSample rule : {InterSample::kZoh, InterSample::kFoh}) {
    Eigen::MatrixXd y;
    ASSERT_TRUE(simulate_state_space(m, rule, uniform(u, ts), y).ok());
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(u.rows(), 2);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        StateSpaceModel<double> pair;
        pair.a = m.a;
        pair.b = m.b.col(j);
        pair.c = m.c.row(i);
        pair.d = m.d.block(i, j, 1, 1);
        const Eigen::MatrixXd uj = u.col(j);
        Eigen::MatrixXd yij;
        if (m.delays(i, j) == std::floor(m.delays(i, j))) {
          // integer: the closed-form reference
          const std::vector<double> steps(u.rows(), ts);
          Eigen::MatrixXi nk(1, 1);
          nk << static_cast<int>(m.delays(i, j));
          yij = reference(pair, uj, steps, rule == InterSample::kFoh, nk);
        } else {
          pair.delays = m.delays.block(i, j, 1, 1);
          ASSERT_TRUE(
              simulate_state_space(pair, rule, uniform(uj, ts), yij).ok());
        }
        sum.col(i) += yij;
      }
    }
    EXPECT_TRUE(MatrixNear(y, sum, kTol));
  }
}

// A fractional delay of half a sample is an integer delay of one sample on
// a grid twice as fine (the input repeated, or interpolated for FOH).
TEST(StateSpaceSimulator, HalfSampleDelayEqualsOneSampleOnFinerGrid) {
  StateSpaceModel<double> m = mimo();
  m.delays = Eigen::MatrixXd::Constant(2, 2, 2.5);
  // at rest first: the FOH ramp up from the zero before the record lasts
  // one interval of each grid, so it differs unless the input starts at 0
  Eigen::MatrixXd u = binary_inputs(80);
  u.topRows(3).setZero();
  const double ts = 0.1;
  for (bool foh : {false, true}) {
    Eigen::MatrixXd fine(2 * u.rows(), 2);
    for (Eigen::Index k = 0; k < u.rows(); ++k) {
      fine.row(2 * k) = u.row(k);
      fine.row(2 * k + 1) = foh && k + 1 < u.rows()
                                ? 0.5 * (u.row(k) + u.row(k + 1))
                                : Eigen::RowVectorXd(u.row(k));
    }
    const InterSample rule = foh ? InterSample::kFoh : InterSample::kZoh;
    Eigen::MatrixXd y;
    ASSERT_TRUE(simulate_state_space(m, rule, uniform(u, ts), y).ok());
    StateSpaceModel<double> fine_model = m;
    fine_model.delays.setConstant(5);
    const std::vector<double> steps(fine.rows(), ts / 2);
    const Eigen::MatrixXd y_fine = reference(
        fine_model, fine, steps, foh, Eigen::MatrixXi::Constant(2, 2, 5));
    Eigen::MatrixXd every_other(u.rows(), 2);
    for (Eigen::Index k = 0; k < u.rows(); ++k) {
      every_other.row(k) = y_fine.row(2 * k);
    }
    // the last coarse interval: the fine input's final value differs (FOH)
    // only after the last coarse sample, which is not compared
    EXPECT_TRUE(MatrixNear(y, every_other, kTol)) << (foh ? "foh" : "zoh");
  }
}

// x = T z with T = diag(1, 1e6, 1e-6): the same input-output map with
// entries of A over twelve decades, simulated as accurately.
TEST(StateSpaceSimulator, BadlyScaledStatesGiveTheSameOutput) {
  StateSpaceModel<double> m;
  m.a.resize(3, 3);
  m.a << -1, 0.5, 0, -0.5, -2, 1, 0, -1, -30;
  m.b.resize(3, 1);
  m.b << 1, 0, 2;
  m.c.resize(1, 3);
  m.c << 1, 1, 0.5;
  m.d = Eigen::MatrixXd::Zero(1, 1);
  const Eigen::VectorXd t(Eigen::Vector3d(1, 1e6, 1e-6));
  StateSpaceModel<double> scaled = m;
  scaled.a = t.asDiagonal().inverse() * m.a * t.asDiagonal();
  scaled.b = t.asDiagonal().inverse() * m.b;
  scaled.c = m.c * t.asDiagonal();
  const Eigen::MatrixXd u = binary_inputs(200).col(0);
  for (InterSample rule : {InterSample::kZoh, InterSample::kFoh}) {
    Eigen::MatrixXd y, ys;
    ASSERT_TRUE(simulate_state_space(m, rule, uniform(u, 0.05), y).ok());
    ASSERT_TRUE(simulate_state_space(scaled, rule, uniform(u, 0.05), ys).ok());
    EXPECT_TRUE(MatrixNear(ys, y, 1e-12));
  }
}

TEST(StateSpaceSimulator, StaticGainWithoutStates) {
  StateSpaceModel<double> m;
  m.a.resize(0, 0);
  m.b.resize(0, 2);
  m.c.resize(1, 0);
  m.d.resize(1, 2);
  m.d << 2, -1;
  m.delays.resize(1, 2);
  m.delays << 0, 2;
  const Eigen::MatrixXd u = binary_inputs(30);
  Eigen::MatrixXd y;
  ASSERT_TRUE(
      simulate_state_space(m, InterSample::kZoh, uniform(u, 1), y).ok());
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    const double delayed = k >= 2 ? u(k - 2, 1) : 0.0;
    EXPECT_DOUBLE_EQ(y(k, 0), 2 * u(k, 0) - delayed) << "sample " << k;
  }
}

TEST(StateSpaceSimulator, RejectsBadModelsAndData) {
  const Eigen::MatrixXd u = binary_inputs(20);
  Eigen::MatrixXd y;
  StateSpaceModel<double> m = mimo();
  m.d.resize(1, 2);
  EXPECT_EQ(
      simulate_state_space(m, InterSample::kZoh, uniform(u, 0.1), y).code(),
      ErrorCode::kDimensionMismatch);
  m = mimo();
  m.delays = Eigen::MatrixXd::Constant(2, 2, -1);
  EXPECT_EQ(
      simulate_state_space(m, InterSample::kZoh, uniform(u, 0.1), y).code(),
      ErrorCode::kBadInput);
  m = mimo();
  EXPECT_EQ(simulate_state_space(m, InterSample::kTrapezoid, uniform(u, 0.1), y)
                .code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(
      simulate_state_space(m, InterSample::kZoh, uniform(u.leftCols(1), 0.1), y)
          .code(),
      ErrorCode::kDimensionMismatch);
  m.delays = Eigen::MatrixXd::Constant(2, 2, 0.5);
  std::vector<double> t(u.rows());
  for (Eigen::Index k = 0; k < u.rows(); ++k) t[k] = 0.1 * k * (1 + 0.01 * k);
  RecordView<double> record = uniform(u, 0);
  record.instants = t.data();
  EXPECT_EQ(simulate_state_space(m, InterSample::kZoh, record, y).code(),
            ErrorCode::kNotSupported);
  m = mimo();
  m.a(0, 0) = 50;  // unstable enough to overflow over the record
  const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(400, 2);
  EXPECT_EQ(
      simulate_state_space(m, InterSample::kZoh, uniform(ones, 5), y).code(),
      ErrorCode::kNumericalFailure);
}

}  // namespace
}  // namespace ctid
