// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/filters/batch_filters.hpp and of the one
// mapping of InterSample to a discretisation (discretization.hpp):
//   - the same record filtered sample by sample (FilterDiscretization +
//     FilterChannel of svf.hpp, the recursive estimators' filters) and in
//     one batch (batch::filter_derivatives, the refined-IV engine's) agrees
//     to rounding, for the exact ZOH, the exact FOH and the trapezoid, on
//     regular and irregular sampling, with the fixed-size and the
//     dynamic-size per-sample kernels;
//   - the exact FOH matrices match an independent computation: a fine-step
//     Runge-Kutta integration of z' = F z + G s with s linear over the
//     interval.
#include "ctid/filters/batch_filters.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ctid/filters/discretization.hpp"
#include "ctid/filters/svf.hpp"

namespace ctid {
namespace {

// A smooth input with some noise, N samples.
std::vector<double> test_signal(int N, double ts) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.1);
  std::vector<double> s(N);
  for (int k = 0; k < N; ++k) {
    const double t = k * ts;
    s[k] = std::sin(1.3 * t) + 0.5 * std::cos(4.1 * t + 0.3) + noise(rng);
  }
  return s;
}

// The denominators: (p + 2)^n for n = 1..4 and a lightly damped second
// order (p^2 + 0.4 p + 25), a sixth order for the dynamic path.
std::vector<Vector<double>> denominators() {
  std::vector<Vector<double>> d;
  for (int n = 1; n <= 4; ++n) d.push_back(svf_denominator<double>(n, 2.0));
  Vector<double> resonant(2);
  resonant << 0.4, 25;
  d.push_back(resonant);
  d.push_back(svf_denominator<double>(6, 3.0));
  return d;
}

// outputs p^i s / D(p), i = 0..n, of every sample by the per-sample stack,
// at rest at the first sample like the batch filters.
Matrix<double> per_sample(const Vector<double>& d, double gain,
                          InterSample rule, FilterKernels kernels,
                          const std::vector<double>& s,
                          const std::vector<double>& t) {
  const int n = static_cast<int>(d.size());
  FilterDiscretization<double> disc;
  disc.configure(n, rule, kernels);
  disc.set_denominator(d);
  FilterChannel<double> channel;
  channel.configure(n);
  channel.set_rest_at_first_sample(true);
  const int N = static_cast<int>(s.size());
  Matrix<double> out(N, n + 1);
  for (int k = 0; k < N; ++k) {
    disc.ensure(k == 0 ? t[1] - t[0] : t[k] - t[k - 1]);
    channel.step(disc, gain, s[k]);
    out.row(k) = channel.outputs().transpose();
  }
  return out;
}

// max |a - b| relative to the largest entry of b, column by column.
double relative_difference(const Matrix<double>& a, const Matrix<double>& b) {
  double worst = 0;
  for (Eigen::Index j = 0; j < b.cols(); ++j) {
    const double scale = b.col(j).cwiseAbs().maxCoeff();
    worst =
        std::max(worst, (a.col(j) - b.col(j)).cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

// Both paths apply the same recursion z_k = Phi z_(k-1) + Gamma0 s_(k-1) +
// Gamma1 (s_k - s_(k-1)) with matrices from the same code (the dynamic
// per-sample path and the batch share discretize()) or from the
// fixed-size kernels, which agree with it to a few units of roundoff
// (companion_kernels_test). The filters are stable, so the rounding of
// each step decays: the difference stays a few hundred roundoffs of the
// largest output, far below 1e-10, while a wrong hold (ZOH for FOH, the
// trapezoid for FOH) differs by 1e-3 or more on this record.
constexpr double kAgreement = 1e-10;

void expect_paths_agree(bool irregular) {
  const int N = 3000;
  const double ts = 0.01;
  const std::vector<double> s = test_signal(N, ts);
  std::vector<double> t(N);
  for (int k = 0; k < N; ++k) {
    t[k] = irregular ? k * ts + 0.004 * (k % 3) : k * ts;
  }
  batch::Clock<double> clock;
  clock.n = N;
  clock.ts = ts;
  clock.instants = irregular ? t.data() : nullptr;
  double worst = 0;
  for (const Vector<double>& d : denominators()) {
    for (InterSample rule :
         {InterSample::kZoh, InterSample::kFoh, InterSample::kTrapezoid}) {
      Matrix<double> batch;
      batch::filter_derivatives<double>(d, 1.5, rule, clock, s.data(), batch);
      for (FilterKernels kernels :
           {FilterKernels::kFixedSize, FilterKernels::kDynamic}) {
        const Matrix<double> recursive =
            per_sample(d, 1.5, rule, kernels, s, t);
        const double difference = relative_difference(recursive, batch);
        worst = std::max(worst, difference);
        EXPECT_LT(difference, kAgreement)
            << "order " << d.size() << ", rule " << static_cast<int>(rule)
            << ", kernels " << static_cast<int>(kernels) << ", irregular "
            << irregular;
      }
    }
  }
  std::printf("largest relative difference, per-sample vs batch: %.2e\n",
              worst);
}

TEST(BatchFilters, PerSampleAndBatchAgreeRegular) { expect_paths_agree(false); }

TEST(BatchFilters, PerSampleAndBatchAgreeIrregular) {
  expect_paths_agree(true);
}

// The agreement above is not trivial: the three rules give different
// outputs on the same record.
TEST(BatchFilters, RulesDiffer) {
  const int N = 500;
  const double ts = 0.05;
  const std::vector<double> s = test_signal(N, ts);
  batch::Clock<double> clock;
  clock.n = N;
  clock.ts = ts;
  Vector<double> d(2);
  d << 0.4, 25;
  Matrix<double> zoh, foh, trapezoid;
  batch::filter_derivatives<double>(d, 1.0, InterSample::kZoh, clock, s.data(),
                                    zoh);
  batch::filter_derivatives<double>(d, 1.0, InterSample::kFoh, clock, s.data(),
                                    foh);
  batch::filter_derivatives<double>(d, 1.0, InterSample::kTrapezoid, clock,
                                    s.data(), trapezoid);
  EXPECT_GT(relative_difference(zoh, foh), 1e-3);
  EXPECT_GT(relative_difference(trapezoid, foh), 1e-3);
}

TEST(Discretisation, MappingOfInterSample) {
  EXPECT_EQ(discretisation_of(InterSample::kZoh), Discretisation::kExactZoh);
  EXPECT_EQ(discretisation_of(InterSample::kFoh), Discretisation::kExactFoh);
  EXPECT_EQ(discretisation_of(InterSample::kTrapezoid),
            Discretisation::kTrapezoid);
}

// z(h) of z' = F z + G (a + b tau/h) from z(0) = z0, by classical
// Runge-Kutta with `steps` steps (error of order (h/steps)^4).
Vector<double> integrate(const Matrix<double>& F, const Matrix<double>& G,
                         double h, const Vector<double>& z0, double a, double b,
                         int steps) {
  const double dt = h / steps;
  auto f = [&](double tau, const Vector<double>& z) -> Vector<double> {
    return F * z + G.col(0) * (a + b * tau / h);
  };
  Vector<double> z = z0;
  for (int i = 0; i < steps; ++i) {
    const double tau = i * dt;
    const Vector<double> k1 = f(tau, z);
    const Vector<double> k2 = f(tau + dt / 2, z + dt / 2 * k1);
    const Vector<double> k3 = f(tau + dt / 2, z + dt / 2 * k2);
    const Vector<double> k4 = f(tau + dt, z + dt * k3);
    z += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return z;
}

// Phi (z0 = e_i, s = 0), Gamma0 (z0 = 0, s = 1) and Gamma1 (z0 = 0, s
// rising from 0 to 1) of the exact FOH against the integration. With 4000
// steps of h ||F|| / 4000 <= 1e-3 the Runge-Kutta error is below 1e-13
// relative; the tolerance, 1e-11, leaves room for the rounding of 4000
// steps.
TEST(Discretisation, ExactFohMatchesIntegration) {
  const int kSteps = 4000;
  for (const Vector<double>& d : denominators()) {
    const int n = static_cast<int>(d.size());
    const Matrix<double> F = companion_matrix<double>(d);
    Matrix<double> G = Matrix<double>::Zero(n, 1);
    G(n - 1, 0) = 1;
    for (double h : {0.01, 0.1, 0.5}) {
      Matrix<double> Phi, Gamma0, Gamma1;
      discretize<double>(Discretisation::kExactFoh, F, G, h, Phi, Gamma0,
                         Gamma1);
      const Vector<double> zero = Vector<double>::Zero(n);
      for (int i = 0; i < n; ++i) {
        const Vector<double> column =
            integrate(F, G, h, Vector<double>::Unit(n, i), 0, 0, kSteps);
        EXPECT_LT((Phi.col(i) - column).norm(), 1e-11 * column.norm())
            << "order " << n << ", h " << h << ", Phi column " << i;
      }
      const Vector<double> g0 = integrate(F, G, h, zero, 1, 0, kSteps);
      const Vector<double> g1 = integrate(F, G, h, zero, 0, 1, kSteps);
      EXPECT_LT((Gamma0.col(0) - g0).norm(), 1e-11 * g0.norm())
          << "order " << n << ", h " << h;
      EXPECT_LT((Gamma1.col(0) - g1).norm(), 1e-11 * g1.norm())
          << "order " << n << ", h " << h;
      // The ZOH Gamma is the FOH Gamma0 (a constant input, no slope).
      Matrix<double> PhiZ, GammaZ, unused;
      discretize<double>(Discretisation::kExactZoh, F, G, h, PhiZ, GammaZ,
                         unused);
      EXPECT_LT((PhiZ - Phi).norm(), 1e-13 * Phi.norm());
      EXPECT_LT((GammaZ - Gamma0).norm(), 1e-13 * Gamma0.norm());
    }
  }
}

// The per-sample exact FOH started as a discrete filter from rest (its
// default) is the batch filter of the record with a ramp from 0 over one
// interval before the first sample, which is the record with one 0 sample
// prepended, its first output dropped.
TEST(Discretisation, FohStartFromRestIsRampFromZero) {
  const int N = 400;
  const double ts = 0.02;
  const std::vector<double> s = test_signal(N, ts);
  std::vector<double> padded(N + 1, 0.0);
  for (int k = 0; k < N; ++k) padded[k + 1] = s[k];
  const Vector<double> d = svf_denominator<double>(3, 4.0);
  batch::Clock<double> clock;
  clock.n = N + 1;
  clock.ts = ts;
  Matrix<double> batch;
  batch::filter_derivatives<double>(d, 1.0, InterSample::kFoh, clock,
                                    padded.data(), batch);
  FilterDiscretization<double> disc;
  disc.configure(3, InterSample::kFoh);
  disc.set_denominator(d);
  FilterChannel<double> channel;
  channel.configure(3);
  Matrix<double> recursive(N, 4);
  for (int k = 0; k < N; ++k) {
    disc.ensure(ts);
    channel.step(disc, 1.0, s[k]);
    recursive.row(k) = channel.outputs().transpose();
  }
  EXPECT_LT(relative_difference(recursive, batch.bottomRows(N)), kAgreement);
}

}  // namespace
}  // namespace ctid
