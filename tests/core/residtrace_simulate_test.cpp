// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/simulate.hpp (and of the
// output terms of model.hpp), against computations written here:
//   - a first-order model K/(p + a) with a held input against its exact ZOH
//     recursion x(k+1) = e^(-a Ts) x(k) + K/a (1 - e^(-a Ts)) u(k), with a
//     delay of whole samples;
//   - the output terms (offset, polynomial, sinusoid, saturation) against
//     their definitions;
//   - a closed loop with a proportional controller against the recursion
//     of the sampled loop;
//   - a constant parameter path equals the time-invariant simulation;
//   - the validation error: the free response of an initial state, the
//     sinusoid's two-fold cross-fitting, the prediction error of a noise
//     model, the start from the beginning of a split record and missing
//     samples;
//   - bad models and records are identified errors.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ctid/apps/residtrace/simulate.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

// K / (p + a) on input 1, from rest.
ResidtraceModel<double> first_order(double K, double a, int nk = 0) {
  ResidtraceModel<double> m;
  m.F = Eigen::Vector2d(1, a);
  m.fixed = {false};
  StructureChannel<double> c;
  c.kind = ChannelKind::kInput;
  c.col = 0;
  c.nb = 1;
  c.nk = nk;
  c.B = Eigen::VectorXd::Constant(1, K);
  m.channels.push_back(c);
  return m;
}

Eigen::VectorXd input(int N, unsigned seed) {
  const std::vector<double> u = test::binary_input(N, 7, seed);
  return Eigen::Map<const Eigen::VectorXd>(u.data(), N);
}

// The exact ZOH recursion of K / (p + a) (x(0) = x0).
Eigen::VectorXd recursion(double K, double a, const Eigen::VectorXd& u,
                          int nk = 0, double x0 = 0) {
  const double phi = std::exp(-a * kTs);
  const double gamma = K / a * (1 - phi);
  Eigen::VectorXd x(u.size());
  double s = x0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    x(k) = s;
    const double uk = k - nk >= 0 ? u(k - nk) : 0.0;
    s = phi * s + gamma * uk;
  }
  return x;
}

OutputTerm<double> term(OutputTermKind kind, std::vector<double> c,
                        double omega = 0) {
  OutputTerm<double> t;
  t.kind = kind;
  t.c = Eigen::Map<const Eigen::VectorXd>(c.data(),
                                          static_cast<Eigen::Index>(c.size()));
  t.omega = omega;
  return t;
}

TEST(ResidtraceSimulate, FirstOrderMatchesExactZohRecursion) {
  const Eigen::VectorXd u = input(300, 3);
  for (int nk : {0, 2}) {
    ModelSimulation<double> sim;
    ASSERT_TRUE(simulate_model<double>(first_order(2.0, 1.5, nk), u, kTs,
                                       nullptr, 10, nullptr, &sim)
                    .ok());
    // rounding of a recursion over 300 samples
    EXPECT_TRUE(test::MatrixNear(sim.y, recursion(2.0, 1.5, u, nk), 1e-12));
    EXPECT_TRUE(test::MatrixNear(sim.uc, u, 0.0));
  }
}

TEST(ResidtraceSimulate, OutputTermsFollowTheirDefinitions) {
  const Eigen::VectorXd u = input(200, 5);
  ResidtraceModel<double> m = first_order(1.0, 2.0);
  m.out.push_back(term(OutputTermKind::kOffset, {0.3}));
  m.out.push_back(term(OutputTermKind::kPolynomial, {0.2, -0.1}));
  m.out.push_back(term(OutputTermKind::kSinusoid, {0.05, -0.02}, 3.0));
  m.out.push_back(term(OutputTermKind::kSaturation, {-0.2, 0.4}));
  ModelSimulation<double> sim;
  ASSERT_TRUE(
      simulate_model<double>(m, u, kTs, nullptr, 1, nullptr, &sim).ok());
  const Eigen::VectorXd x = recursion(1.0, 2.0, u);
  Eigen::VectorXd y(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const double t = k * kTs;
    const double v = x(k) + 0.3 + 0.2 * x(k) * x(k) - 0.1 * std::pow(x(k), 3) +
                     0.05 * std::sin(3 * t) - 0.02 * std::cos(3 * t);
    y(k) = std::min(std::max(v, -0.2), 0.4);
  }
  EXPECT_TRUE(test::MatrixNear(sim.x, x, 1e-12));
  EXPECT_TRUE(test::MatrixNear(sim.y, y, 1e-12));
  EXPECT_GT((sim.y.array() == 0.4).count(), 0);  // the clip acts
}

TEST(ResidtraceSimulate, ClosedLoopMatchesSampledLoopRecursion) {
  // u(k) = r1(k) + Kc (r2(k) - y(k)), y = x + c; x(k+1) from the held u(k)
  const int N = 250;
  const double K = 1.2, a = 0.8, Kc = 0.7, c = 0.25;
  ResidtraceModel<double> m = first_order(K, a);
  m.out.push_back(term(OutputTermKind::kOffset, {c}));
  ClosedLoop<double> loop;
  loop.num = Eigen::VectorXd::Constant(1, Kc);
  loop.den = Eigen::VectorXd::Constant(1, 1.0);
  loop.r1 = 0.1 * input(N, 7);
  loop.r2 = input(N, 11);
  ModelSimulation<double> sim;
  ASSERT_TRUE(simulate_model<double>(m, Eigen::MatrixXd::Zero(N, 1), kTs, &loop,
                                     4, nullptr, &sim)
                  .ok());
  const double phi = std::exp(-a * kTs), gamma = K / a * (1 - phi);
  Eigen::VectorXd y(N), u1(N);
  double x = 0;
  for (int k = 0; k < N; ++k) {
    y(k) = x + c;
    u1(k) = loop.r1(k) + Kc * (loop.r2(k) - y(k));
    x = phi * x + gamma * u1(k);
  }
  // four sub-steps of the held input compose to the interval's map
  EXPECT_TRUE(test::MatrixNear(sim.y, y, 1e-11));
  EXPECT_TRUE(test::MatrixNear(sim.uc.col(0), u1, 1e-11));
}

TEST(ResidtraceSimulate, ConstantParameterPathEqualsTimeInvariantModel) {
  const int N = 150;
  const Eigen::VectorXd u = input(N, 13);
  ResidtraceModel<double> m = first_order(0.9, 1.1);
  Eigen::MatrixXd thm(N, 2);
  thm.col(0).setConstant(1.1);
  thm.col(1).setConstant(0.9);
  ModelSimulation<double> lti, ltv;
  ASSERT_TRUE(
      simulate_model<double>(m, u, kTs, nullptr, 1, nullptr, &lti).ok());
  ASSERT_TRUE(simulate_model<double>(m, u, kTs, nullptr, 1, &thm, &ltv).ok());
  EXPECT_TRUE(test::MatrixNear(ltv.y, lti.y, 1e-12));
  // a channel fed by the output sends the path to the effect simulator,
  // whose sub-steps are exact for the held input too
  m.out.push_back(term(OutputTermKind::kOffset, {0.0}));
  StructureChannel<double> sv = m.channels[0];
  sv.kind = ChannelKind::kSignV;
  sv.B = Eigen::VectorXd::Zero(1);
  m.channels.push_back(sv);
  Eigen::MatrixXd thm2(N, 3);
  thm2 << thm, Eigen::VectorXd::Zero(N);
  ModelSimulation<double> eff;
  ASSERT_TRUE(simulate_model<double>(m, u, kTs, nullptr, 3, &thm2, &eff).ok());
  EXPECT_TRUE(test::MatrixNear(eff.y, lti.y, 1e-11));
}

TEST(ResidtraceValidation, InitialStateSinusoidAndSplitRecord) {
  const int N = 400, npre = 100;
  const Eigen::VectorXd u = input(N + npre, 17);
  ResidtraceModel<double> m = first_order(1.5, 2.0);
  // a record that starts at x0 = 0.7: the free response e^(-2 t) x0
  const Eigen::VectorXd x = recursion(1.5, 2.0, u.tail(N), 0, 0.7);
  ValidationRecord<double> V;
  V.y = x;
  V.u = u.tail(N);
  V.ts = kTs;
  Eigen::VectorXd e, yh;
  ASSERT_TRUE(validation_error<double>(m, V, 1, &e, &yh).ok());
  EXPECT_GT(e.cwiseAbs().maxCoeff(), 0.1);  // from rest: the error of x0
  m.x0 = true;
  ASSERT_TRUE(validation_error<double>(m, V, 1, &e, &yh).ok());
  EXPECT_LT(e.cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_TRUE(test::MatrixNear(yh, x, 1e-10));
  // a sinusoid of unknown phase: fitted on each half, applied to the other
  m.x0 = false;
  m.out.push_back(term(OutputTermKind::kSinusoid, {0, 0}, 2.5));
  ValidationRecord<double> W = V;
  W.u = u.tail(N);
  W.u_pre = u.head(npre);
  const Eigen::VectorXd xs = recursion(1.5, 2.0, u).tail(N);
  for (int k = 0; k < N; ++k) {
    W.y(k) = xs(k) + 0.3 * std::sin(2.5 * k * kTs + 1.0);
  }
  ASSERT_TRUE(validation_error<double>(m, W, 1, &e, &yh).ok());
  EXPECT_LT(e.cwiseAbs().maxCoeff(), 1e-10);
  // missing samples carry no error; yh is the record there
  W.missing.assign(N, false);
  W.missing[5] = W.missing[300] = true;
  W.y(5) += 1;
  W.y(300) -= 1;
  ASSERT_TRUE(validation_error<double>(m, W, 1, &e, &yh).ok());
  EXPECT_EQ(e(5), 0.0);
  EXPECT_EQ(yh(300), W.y(300));
}

TEST(ResidtraceValidation, NoiseModelGivesThePredictionError) {
  const int N = 120;
  const Eigen::VectorXd u = input(N, 19);
  ResidtraceModel<double> m = first_order(1.0, 1.0);
  ValidationRecord<double> V;
  V.u = u;
  V.ts = kTs;
  Eigen::VectorXd d(N);
  for (int k = 0; k < N; ++k) d(k) = std::sin(0.3 * k) + 0.1 * (k % 5);
  V.y = recursion(1.0, 1.0, u) + d;
  m.noise = Eigen::Vector3d(1, -0.5, 0.2);
  Eigen::VectorXd e, yh;
  ASSERT_TRUE(validation_error<double>(m, V, 1, &e, &yh).ok());
  Eigen::VectorXd p(N);
  for (int k = 0; k < N; ++k) {
    p(k) = d(k) - 0.5 * (k >= 1 ? d(k - 1) : 0) + 0.2 * (k >= 2 ? d(k - 2) : 0);
  }
  EXPECT_TRUE(test::MatrixNear(e, p, 1e-12));
  EXPECT_TRUE(test::MatrixNear(yh, V.y - p, 1e-12));
}

TEST(ResidtraceSimulate, BadModelsAreIdentifiedErrors) {
  const Eigen::VectorXd u = input(20, 1);
  ModelSimulation<double> sim;
  ResidtraceModel<double> m = first_order(1.0, 1.0);
  m.fixed.clear();
  EXPECT_EQ(simulate_model<double>(m, u, kTs, nullptr, 1, nullptr, &sim).code(),
            ErrorCode::kDimensionMismatch);
  m = first_order(1.0, 1.0);
  m.channels[0].B = Eigen::Vector3d(1, 1, 1);  // improper
  EXPECT_EQ(simulate_model<double>(m, u, kTs, nullptr, 1, nullptr, &sim).code(),
            ErrorCode::kBadInput);
  m = first_order(1.0, 1.0);
  m.out.push_back(term(OutputTermKind::kPolynomial, {0.1}));
  EXPECT_EQ(simulate_model<double>(m, u, kTs, nullptr, 1, nullptr, &sim).code(),
            ErrorCode::kBadInput);
  m = first_order(1.0, 1.0);
  m.has_phys = true;
  ClosedLoop<double> loop;
  loop.num = loop.den = Eigen::VectorXd::Ones(1);
  loop.r1 = loop.r2 = u;
  EXPECT_EQ(simulate_model<double>(m, u, kTs, &loop, 1, nullptr, &sim).code(),
            ErrorCode::kNotSupported);
  m = first_order(1.0, 1.0);
  m.channels[0].kind = ChannelKind::kNode;
  EXPECT_EQ(simulate_model<double>(m, u, kTs, &loop, 1, nullptr, &sim).code(),
            ErrorCode::kNotSupported);
}

}  // namespace
}  // namespace ctid::residtrace
