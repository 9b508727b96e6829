// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/model_fit.hpp:
//   - residualised: a real pole far beyond the samples removed, the
//     numerators divided by it (the static gain kept), integrators kept
//     fixed; nothing to remove, or a numerator that would become improper,
//     leaves the model;
//   - fit_model recovers a noise-free first-order model (SRIVC is exact on
//     noise-free ZOH data), and a template with a pole at p Ts = 1e4 is
//     fitted in the order without it;
//   - with an output-power channel the residual variance is that of the
//     fitted model's simulation error, recomputed here by simulate_model.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ctid/apps/residtrace/model_fit.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

ResidtraceModel<double> model(const Eigen::VectorXd& F,
                              const Eigen::VectorXd& B) {
  ResidtraceModel<double> m;
  m.F = F;
  m.fixed.assign(static_cast<std::size_t>(F.size() - 1), false);
  StructureChannel<double> c;
  c.col = 0;
  c.nb = static_cast<int>(B.size());
  c.B = B;
  m.channels.push_back(c);
  return m;
}

FitRecord<double> record(const ResidtraceModel<double>& truth, int N,
                         unsigned seed) {
  const std::vector<double> u = test::binary_input(N, 9, seed);
  FitRecord<double> D;
  D.u = Eigen::Map<const Eigen::VectorXd>(u.data(), N);
  D.ts = kTs;
  ModelSimulation<double> sim;
  EXPECT_TRUE(
      simulate_model<double>(truth, D.u, kTs, nullptr, 1, nullptr, &sim).ok());
  D.y = sim.y;
  D.ysm = sim.y;
  return D;
}

TEST(ResidtraceModelFit, ResidualisedRemovesTheFastPoleOnly) {
  // (p + 2)(p + 1e6) p, an integrator fixed; B = 3e6: gain 3 / (p (p + 2))
  ResidtraceModel<double> m = model(Eigen::Vector4d(1, 2 + 1e6, 2e6, 0),
                                    Eigen::VectorXd::Constant(1, 3e6));
  m.fixed = {false, false, true};
  ResidtraceModel<double> red;
  ASSERT_TRUE(residualised<double>(m, kTs, 1000, false, &red));
  EXPECT_TRUE(test::MatrixNear(red.F, Eigen::Vector3d(1, 2, 0), 1e-9));
  EXPECT_EQ(red.fixed, (std::vector<bool>{false, true}));
  EXPECT_NEAR(red.channels[0].B(0), 3.0, 3e-9);
  // nothing beyond the limit
  EXPECT_FALSE(residualised<double>(red, kTs, 1000, false, &red));
  // a numerator as long as the reduced order: kept unless trimmed
  ResidtraceModel<double> b =
      model(Eigen::Vector3d(1, 1 + 1e6, 1e6), Eigen::Vector2d(1e6, 2e6));
  EXPECT_FALSE(residualised<double>(b, kTs, 1000, false, &red));
  ASSERT_TRUE(residualised<double>(b, kTs, 1000, true, &red));
  EXPECT_EQ(red.channels[0].nb, 1);
  EXPECT_NEAR(red.channels[0].B(0), 2.0, 1e-9);
}

TEST(ResidtraceModelFit, RecoversFirstOrderAndDropsAFastPole) {
  const ResidtraceModel<double> truth =
      model(Eigen::Vector2d(1, 1.5), Eigen::VectorXd::Constant(1, 2.0));
  const FitRecord<double> D = record(truth, 600, 23);
  ModelFitSettings s;
  ResidtraceModel<double> fit;
  ASSERT_TRUE(
      fit_model<double>(truth, D, {Eigen::Vector2d(1, 1.0)}, s, &fit).ok());
  ASSERT_TRUE(fit.estimate.ok);
  EXPECT_TRUE(test::MatrixNear(fit.F, truth.F, 1e-6));
  EXPECT_NEAR(fit.channels[0].B(0), 2.0, 2e-6);
  EXPECT_EQ(fit.estimate.np, 2);
  // a template with a pole at p Ts = 1e4 (as a fit that ran off leaves
  // one): fitted in first order
  const double p = 2e5;
  ResidtraceModel<double> tmpl = model(Eigen::Vector3d(1, 1.5 + p, 1.5 * p),
                                       Eigen::VectorXd::Constant(1, 2.0 * p));
  ResidtraceModel<double> red;
  ASSERT_TRUE(residualised<double>(tmpl, kTs, 1000, false, &red));
  ASSERT_TRUE(fit_model<double>(red, D, {red.F}, s, &fit).ok());
  ASSERT_TRUE(fit.estimate.ok);
  EXPECT_EQ(fit.F.size(), 2);
  EXPECT_TRUE(test::MatrixNear(fit.F, truth.F, 1e-6));
}

TEST(ResidtraceModelFit, OutputPowerVarianceIsTheSimulationError) {
  // p x + 1.0 x = 1.5 u - 0.3 x^3 (a hardening term), noise added
  ResidtraceModel<double> truth =
      model(Eigen::Vector2d(1, 1.0), Eigen::VectorXd::Constant(1, 1.5));
  StructureChannel<double> yp;
  yp.kind = ChannelKind::kOutputPower;
  yp.param = 3;
  yp.nb = 1;
  yp.B = Eigen::VectorXd::Constant(1, -0.3);
  truth.channels.push_back(yp);
  OutputTerm<double> off;
  off.kind = OutputTermKind::kOffset;
  off.c = Eigen::VectorXd::Zero(1);
  truth.out.push_back(off);
  FitRecord<double> D = record(truth, 500, 29);
  for (Eigen::Index k = 0; k < D.y.size(); ++k) {
    D.y(k) += 0.01 * std::sin(1.7 * k) * std::cos(0.37 * k * k);
  }
  D.ysm = D.y;
  ModelFitSettings s;
  s.substeps = 10;
  ResidtraceModel<double> fit;
  ASSERT_TRUE(fit_model<double>(truth, D, {truth.F}, s, &fit).ok());
  ASSERT_TRUE(fit.estimate.ok);
  ModelSimulation<double> sim;
  ASSERT_TRUE(
      simulate_model<double>(fit, D.u, kTs, nullptr, 10, nullptr, &sim).ok());
  const Eigen::VectorXd e = D.y - sim.y;
  const double s2 = e.squaredNorm() / (D.y.size() - fit.estimate.np);
  EXPECT_NEAR(fit.estimate.s2, s2, 1e-12 * s2);
  EXPECT_TRUE(test::MatrixNear(fit.estimate.e, e, 1e-12));
  EXPECT_NEAR(fit.channels[1].B(0), -0.3, 0.05);
}

}  // namespace
}  // namespace ctid::residtrace
