// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/physical_reading.hpp:
//   - the poles of F = (p + 2)(p + 5)(p^2 + 2p + 10), built from its roots:
//     time constants 1/2 and 1/5, natural frequency sqrt(10) and damping
//     1/sqrt(10); the static gain b0/100; the zeros of B = (p - 1)(p - 2);
//     the delay (nk + f) Ts;
//   - a double integrator with damping, F = [1 f1 0], B = b0: the gain
//     b0/f1 after one integrator, a pole 0, the mass 1/b0 and the viscous
//     coefficient f1/b0, whose standard deviations are sqrt(J C J') with
//     the Jacobian J of the same ratios by central differences;
//   - an added Coulomb channel, -b_s/b0 in input units, its std likewise;
//     an offset channel b_c/b0; the drift's Qn and the AR noise order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/physical_reading.hpp"

namespace ctid::residtrace {
namespace {

StructureChannel<double> channel(ChannelKind kind, const Eigen::VectorXd& B) {
  StructureChannel<double> c;
  c.kind = kind;
  c.nb = static_cast<int>(B.size());
  c.B = B;
  return c;
}

// The values of the quantities named name, in order.
std::vector<double> values(const std::vector<PhysicalQuantity<double>>& p,
                           const std::string& name) {
  std::vector<double> v;
  for (const auto& q : p) {
    if (q.name == name) v.push_back(q.value.at(0).real());
  }
  return v;
}

const PhysicalQuantity<double>& find(
    const std::vector<PhysicalQuantity<double>>& p, const std::string& name) {
  for (const auto& q : p) {
    if (q.name == name) return q;
  }
  ADD_FAILURE() << "no quantity " << name;
  return p.front();
}

// sqrt(J C J') with J the central-difference Jacobian of g at theta.
double delta_std(const std::function<double(const Eigen::VectorXd&)>& g,
                 const Eigen::VectorXd& theta, const Eigen::MatrixXd& C) {
  Eigen::RowVectorXd J(theta.size());
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(theta(i)));
    Eigen::VectorXd a = theta, b = theta;
    a(i) += h;
    b(i) -= h;
    J(i) = (g(a) - g(b)) / (2 * h);
  }
  return std::sqrt((J * C * J.transpose())(0, 0));
}

TEST(PhysicalReading, PolesZerosGainAndDelay) {
  // (p + 2)(p + 5) = p^2 + 7p + 10, times p^2 + 2p + 10
  const Eigen::VectorXd a = (Eigen::VectorXd(3) << 1, 7, 10).finished();
  const Eigen::VectorXd c = (Eigen::VectorXd(3) << 1, 2, 10).finished();
  ResidtraceModel<double> m;
  m.F = convolve<double>(a, c);
  m.fixed.assign(4, false);
  m.channels.push_back(channel(ChannelKind::kInput,
                               (Eigen::VectorXd(3) << 3, -9, 6).finished()));
  m.channels[0].nk = 2;
  m.channels[0].param = 0.25;
  const auto p = physical_reading<double>(m, 0.1, ReadingLabels<double>());
  EXPECT_EQ(p.front().name, "static gain");
  EXPECT_NEAR(p.front().value.at(0).real(), 6.0 / 100, 1e-14);
  std::vector<double> tau = values(p, "time constant (s)");
  std::sort(tau.begin(), tau.end());
  ASSERT_EQ(tau.size(), 2u);
  EXPECT_NEAR(tau[0], 0.2, 1e-12);
  EXPECT_NEAR(tau[1], 0.5, 1e-12);
  const auto wn = values(p, "natural frequency (rad/s)");
  const auto zeta = values(p, "damping ratio");
  ASSERT_EQ(wn.size(), 1u);
  ASSERT_EQ(zeta.size(), 1u);
  EXPECT_NEAR(wn[0], std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(zeta[0], 1 / std::sqrt(10.0), 1e-12);
  std::vector<double> z = values(p, "zero");
  std::sort(z.begin(), z.end());
  ASSERT_EQ(z.size(), 2u);
  EXPECT_NEAR(z[0], 1, 1e-12);
  EXPECT_NEAR(z[1], 2, 1e-12);
  EXPECT_NEAR(values(p, "delay (s)").at(0), 2.25 * 0.1, 1e-15);
  for (const auto& q : p) EXPECT_TRUE(std::isnan(q.std)) << q.name;
}

TEST(PhysicalReading, MassViscousAndAddedChannelsByTheDeltaMethod) {
  const double f1 = 0.8, b0 = 2.5, bs = -0.4, bc = 0.3;
  ResidtraceModel<double> m;
  m.F = (Eigen::VectorXd(3) << 1, f1, 0).finished();
  m.fixed = {false, true};
  m.channels.push_back(
      channel(ChannelKind::kInput, Eigen::VectorXd::Constant(1, b0)));
  m.channels.push_back(
      channel(ChannelKind::kSignV, Eigen::VectorXd::Constant(1, bs)));
  m.channels.push_back(
      channel(ChannelKind::kConstant, Eigen::VectorXd::Constant(1, bc)));
  // theta = [f1 b0 bs bc], a covariance with correlations
  Eigen::MatrixXd L(4, 4);
  L << 0.1, 0, 0, 0, 0.03, 0.2, 0, 0, -0.02, 0.05, 0.1, 0, 0.01, -0.04, 0.02,
      0.05;
  m.estimate.cov = L * L.transpose();
  const Eigen::VectorXd theta =
      (Eigen::VectorXd(4) << f1, b0, bs, bc).finished();
  m.noise = (Eigen::VectorXd(3) << 1, -0.5, 0.1).finished();
  ReadingLabels<double> x;
  x.channel_names = {"u1", "sign(v)", "1"};
  x.drift_q = (Eigen::VectorXd(2) << 1e-3, 2e-3).finished();
  const auto p = physical_reading<double>(m, 0.1, x);
  EXPECT_EQ(p.front().name, "gain after 1 integrator(s)");
  EXPECT_NEAR(p.front().value.at(0).real(), b0 / f1, 1e-14);
  EXPECT_EQ(values(p, "pole").size(), 1u);
  EXPECT_NEAR(values(p, "time constant (s)").at(0), 1 / f1, 1e-12);
  const auto& C = m.estimate.cov;
  const auto& mass = find(p, "mass 1/b0");
  EXPECT_NEAR(mass.value.at(0).real(), 1 / b0, 1e-15);
  EXPECT_NEAR(
      mass.std,
      delta_std([](const Eigen::VectorXd& t) { return 1 / t(1); }, theta, C),
      1e-8);
  const auto& visc = find(p, "viscous coefficient f1/b0");
  EXPECT_NEAR(visc.value.at(0).real(), f1 / b0, 1e-15);
  EXPECT_NEAR(
      visc.std,
      delta_std([](const Eigen::VectorXd& t) { return t(0) / t(1); }, theta, C),
      1e-8);
  const auto& coulomb = find(p, "Coulomb level -b_s/b0");
  EXPECT_NEAR(coulomb.value.at(0).real(), -bs / b0, 1e-15);
  EXPECT_NEAR(coulomb.std,
              delta_std([](const Eigen::VectorXd& t) { return -t(2) / t(1); },
                        theta, C),
              1e-8);
  const auto& offset = find(p, "input offset b_c/b0");
  EXPECT_NEAR(offset.value.at(0).real(), bc / b0, 1e-15);
  EXPECT_NEAR(
      offset.std,
      delta_std([](const Eigen::VectorXd& t) { return t(3) / t(1); }, theta, C),
      1e-8);
  EXPECT_EQ(values(p, "Qn(2,2)").at(0), 2e-3);
  EXPECT_EQ(values(p, "AR noise order").at(0), 2);
}

}  // namespace
}  // namespace ctid::residtrace
