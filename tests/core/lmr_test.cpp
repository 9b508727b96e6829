// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/adaptation/lmr.hpp: LMR-RLSSVF, eq. (3.82), against the
// covariance-form least squares it generalises, its bounded information
// under poor excitation (sec. 3.6.3), its square-root information form in
// single precision against the same recursion summed in double, the guard
// on R (floor and ceiling), and no allocation per step.
#include "ctid/adaptation/lmr.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "allocation_counter.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

struct Regression {
  Eigen::MatrixXd phi;  // one regressor per column
  Eigen::VectorXd target;
};

Regression random_regression(int n, int np, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Regression r;
  r.phi.resize(np, n);
  r.target.resize(n);
  Eigen::VectorXd theta = Eigen::VectorXd::LinSpaced(np, 1, 2);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < np; ++i) r.phi(i, k) = normal(rng) * (i + 1);
    theta(0) += 0.01 * normal(rng);  // a drifting parameter
    r.target(k) = r.phi.col(k).dot(theta) + 0.1 * normal(rng);
  }
  return r;
}

// R(t_k) = lambda R + phi phi^T + (1 - lambda) Gamma with Gamma = 0 is the
// inverse of the forgetting-factor P of eq. (1.57), and the gain R^-1 phi
// is P(t_k) phi = the RLS gain: the estimates coincide.
TEST(LmrUpdate, WithZeroGammaItIsTheForgettingFactorRls) {
  const int np = 3;
  const Regression r = random_regression(500, np, 1);
  const Eigen::VectorXd theta0 = Eigen::VectorXd::Zero(np);
  const Eigen::MatrixXd P0 = 100 * Eigen::MatrixXd::Identity(np, np);
  for (double lambda : {1.0, 0.97}) {
    LmrUpdate<double> lmr;
    lmr.configure(np, lambda, Eigen::MatrixXd::Zero(np, np));
    lmr.reset(theta0, P0);
    ParameterUpdate<double> rls(np, ForgettingFactorAdaptation<double>(lambda));
    rls.reset(theta0, P0);
    for (int k = 0; k < r.target.size(); ++k) {
      const double e1 = lmr.update(r.phi.col(k), r.target(k));
      const double e2 = rls.update(r.phi.col(k), r.target(k));
      ASSERT_NEAR(e1, e2, 1e-9 * (1 + std::abs(e2))) << k;
    }
    EXPECT_TRUE(test::MatrixNear(lmr.theta(), rls.theta(), 1e-10));
    EXPECT_TRUE(test::MatrixNear(lmr.P(), rls.P(), 1e-8));
    EXPECT_FALSE(lmr.failed());
    EXPECT_EQ(lmr.covariance_guard(), kGuardNone);
  }
}

// With lambda = 1 the regularisation term (1 - lambda) Gamma vanishes.
TEST(LmrUpdate, WithUnitLambdaGammaHasNoEffect) {
  const Regression r = random_regression(300, 2, 2);
  LmrUpdate<double> a, b;
  a.configure(2, 1.0, Eigen::MatrixXd::Identity(2, 2));
  b.configure(2, 1.0, Eigen::MatrixXd::Zero(2, 2));
  a.reset(Eigen::VectorXd::Zero(2), Eigen::MatrixXd::Identity(2, 2));
  b.reset(Eigen::VectorXd::Zero(2), Eigen::MatrixXd::Identity(2, 2));
  for (int k = 0; k < r.target.size(); ++k) {
    a.update(r.phi.col(k), r.target(k));
    b.update(r.phi.col(k), r.target(k));
  }
  EXPECT_TRUE(test::MatrixNear(a.theta(), b.theta(), 0.0));
}

// Poor excitation (phi = 0 after a rich start): the forgetting-factor P
// grows as lambda^-k (eq. 3.77), while R of eq. (3.82) tends to Gamma:
// R_k = lambda^k R_0 + (1 - lambda^k) Gamma, so kappa_2 stays bounded by
// max(kappa_2(R_0), kappa_2(Gamma)) terms and the estimate does not move.
TEST(LmrUpdate, KeepsTheInformationBoundedWithoutExcitation) {
  const int np = 3;
  const double lambda = 0.99;
  const Eigen::MatrixXd gamma = Eigen::Vector3d(1, 2, 3).asDiagonal();
  const Regression r = random_regression(200, np, 3);
  LmrUpdate<double> lmr;
  lmr.configure(np, lambda, gamma);
  lmr.reset(Eigen::VectorXd::Zero(np), 1e4 * Eigen::MatrixXd::Identity(np, np));
  ParameterUpdate<double> ff(np, ForgettingFactorAdaptation<double>(lambda));
  ff.reset(Eigen::VectorXd::Zero(np), 1e4 * Eigen::MatrixXd::Identity(np, np));
  for (int k = 0; k < r.target.size(); ++k) {
    lmr.update(r.phi.col(k), r.target(k));
    ff.update(r.phi.col(k), r.target(k));
  }
  const Eigen::VectorXd theta = lmr.theta();
  const Eigen::MatrixXd R0 = lmr.information();
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const int idle = 2000;
  for (int k = 0; k < idle; ++k) {
    lmr.update(zero, 0.0);
    ff.update(zero, 0.0);
  }
  const double decay = std::pow(lambda, idle);
  const Eigen::MatrixXd expected = decay * R0 + (1 - decay) * gamma;
  EXPECT_TRUE(test::MatrixNear(lmr.information(), expected, 1e-9));
  EXPECT_TRUE(test::MatrixNear(lmr.theta(), theta, 0.0));
  // lambda^2000 R0 adds about 2e-9 * 1e3 relative to Gamma.
  EXPECT_LT(lmr.condition_number(), 3.0 * (1 + 1e-4));
  // The forgetting factor's P has grown by lambda^-2000 ~ 2e8.
  EXPECT_GT(ff.P().norm(), 1e6 * 1e-4);
}

// Eq. (3.82) as written, in information form summed in double with
// Eigen (R = lambda R + phi phi^T + (1 - lambda) Gamma, theta += R^-1 phi
// epsilon), against the square-root step at the compile-time size and at
// the runtime size: an independent reference for both, with a Gamma that
// acts (lambda < 1).
TEST(LmrUpdate, AtBothSizesItIsTheTextbookInformationRecursion) {
  for (int np : {1, 3, 5}) {
    const Regression r = random_regression(400, np, 7 + np);
    const double lambda = 0.95;
    Eigen::MatrixXd gamma(np, np);
    for (int i = 0; i < np; ++i) {
      for (int j = 0; j < np; ++j) gamma(i, j) = 0.2 / (1 + std::abs(i - j));
    }
    gamma.diagonal().array() += 0.5;
    const Eigen::VectorXd theta0 = Eigen::VectorXd::Constant(np, 0.3);
    const Eigen::MatrixXd P0 = 10 * Eigen::MatrixXd::Identity(np, np);
    for (bool fixed : {true, false}) {
      LmrUpdate<double> lmr;
      lmr.configure(np, lambda, gamma, true, fixed);
      ASSERT_EQ(lmr.fixed_size(), fixed ? np : 0);
      lmr.reset(theta0, P0);
      Eigen::MatrixXd R = P0.inverse();
      Eigen::VectorXd theta = theta0;
      for (int k = 0; k < r.target.size(); ++k) {
        const Eigen::VectorXd phi = r.phi.col(k);
        const double e = r.target(k) - phi.dot(theta);
        R = lambda * R + phi * phi.transpose() + (1 - lambda) * gamma;
        theta += R.ldlt().solve(phi) * e;
        const double e_lmr = lmr.update(phi, r.target(k));
        ASSERT_NEAR(e_lmr, e, 1e-9 * (1 + std::abs(e))) << np << " " << k;
      }
      EXPECT_TRUE(test::MatrixNear(lmr.theta(), theta, 1e-9)) << np;
      EXPECT_TRUE(test::MatrixNear(lmr.information(), R, 1e-9)) << np;
      EXPECT_EQ(lmr.covariance_guard(), kGuardNone);
    }
  }
}

TEST(LmrUpdate, UpdateDoesNotAllocate) {
  const int np = 4;
  LmrUpdate<double> lmr;
  lmr.configure(np, 0.99, Eigen::MatrixXd::Identity(np, np));
  lmr.reset(Eigen::VectorXd::Zero(np), Eigen::MatrixXd::Identity(np, np));
  Eigen::VectorXd phi = Eigen::VectorXd::Ones(np);
  lmr.update(phi, 1.0);
  const long before = g_allocations.load();
  for (int k = 0; k < 1000; ++k) {
    phi(k % np) = std::sin(k);
    lmr.update(phi, std::cos(k));
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
}

// The loss of R under poor excitation: one direction excited (a constant
// input), lambda = 0.998, Gamma = 1e-3 I, in single precision. R summed in
// float had a negative eigenvalue within 6 000 such samples of the long-run
// scenario (rounding of the large excited part, ~eps |R| per step, kept for
// 1 / (1 - lambda) steps, is as large as Gamma). The factor form must keep
// R = L L^T close to the same recursion summed in double from the
// same float regressors: its smallest eigenvalue (Gamma's level) within
// 5 %, its largest within 1e-4, and the guard must not have been needed.
TEST(LmrUpdate, SinglePrecisionFactorFollowsTheDoubleRecursion) {
  const int np = 3;
  const float lambda = 0.998f;
  LmrUpdate<float> lmr;
  lmr.configure(np, lambda, 1e-3f * Eigen::MatrixXf::Identity(np, np));
  lmr.reset(Eigen::VectorXf::Zero(np), 1e4f * Eigen::MatrixXf::Identity(np, np));
  Eigen::MatrixXd R = 1e-4 * Eigen::MatrixXd::Identity(np, np);
  std::mt19937 rng(5);
  std::normal_distribution<float> normal;
  const Eigen::Vector3f direction(-0.6f, -1.1f, 1.4f);
  int guarded = 0;
  for (int k = 0; k < 200000; ++k) {
    Eigen::Vector3f phi = direction;
    if (k < 2000) {
      for (int i = 0; i < np; ++i) phi(i) = normal(rng);
    } else {
      phi *= 1 + 1e-4f * normal(rng);
    }
    const float target = phi.dot(Eigen::Vector3f(1, 2, 3)) + 0.01f * normal(rng);
    lmr.update(phi, target);
    guarded += lmr.covariance_guard() != kGuardNone;
    const Eigen::Vector3d p = phi.cast<double>();
    R = lambda * R + p * p.transpose() +
        (1 - double(lambda)) * 1e-3 * Eigen::MatrixXd::Identity(np, np);
  }
  ASSERT_FALSE(lmr.failed());
  EXPECT_EQ(guarded, 0);
  const Eigen::MatrixXd Rf = lmr.information().cast<double>();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ef(Rf), ed(R);
  EXPECT_NEAR(ef.eigenvalues()(0) / ed.eigenvalues()(0), 1, 0.05)
      << ef.eigenvalues().transpose() << " vs " << ed.eigenvalues().transpose();
  EXPECT_NEAR(ef.eigenvalues()(2) / ed.eigenvalues()(2), 1, 1e-4);
  EXPECT_TRUE(lmr.P().allFinite());
  EXPECT_TRUE(lmr.theta().allFinite());
}

// Without Gamma a forgetting factor < 1 lets R decay as lambda^k in the
// directions not excited (windup, eq. 3.77): in float 0.99^10000 = 2e-44
// underflows. The guard's floor keeps R_jj at the smaller of
// 1/sqrt(max) and R(t_0)'s smallest diagonal entry, so P stays finite and
// positive definite and the estimate stays put; without the guard P is
// lost.
TEST(LmrUpdate, GuardFloorBoundsTheWindupWithoutGamma) {
  const int np = 2;
  for (const bool guard : {true, false}) {
    LmrUpdate<float> lmr;
    lmr.configure(np, 0.99f, Eigen::MatrixXf::Zero(np, np), guard);
    lmr.reset(Eigen::VectorXf::Zero(np), Eigen::MatrixXf::Identity(np, np));
    int repairs = 0;
    for (int k = 0; k < 10000; ++k) {
      lmr.update(Eigen::Vector2f(1, 0), 2.0f);
      repairs += (lmr.covariance_guard() & kGuardRepair) != 0;
    }
    const Eigen::MatrixXf P = lmr.P();
    if (guard) {
      EXPECT_GT(repairs, 0);
      EXPECT_FALSE(lmr.failed());
      ASSERT_TRUE(P.allFinite()) << P;
      EXPECT_TRUE(Eigen::LLT<Eigen::MatrixXf>(P).info() == Eigen::Success);
      const float floor = 1 / std::sqrt(std::numeric_limits<float>::max());
      EXPECT_NEAR(lmr.information()(1, 1) / floor, 1, 1e-3);
      EXPECT_NEAR(lmr.theta()(0), 2, 1e-5);
      EXPECT_EQ(lmr.theta()(1), 0);
    } else {
      EXPECT_EQ(repairs, 0);
      EXPECT_FALSE(P.allFinite());
    }
  }
}

// lambda = 1 and a large regressor: R_11 grows as k phi_1^2 past
// sqrt(max) of float; the ceiling scales row 1 of L (R <- E R E), which
// keeps R's correlations and R finite.
TEST(LmrUpdate, GuardCeilingIsACongruence) {
  LmrUpdate<float> lmr;
  lmr.configure(2, 1.0f, Eigen::MatrixXf::Zero(2, 2));
  lmr.reset(Eigen::VectorXf::Zero(2), Eigen::MatrixXf::Identity(2, 2));
  std::mt19937 rng(3);
  std::normal_distribution<float> normal;
  int ceilings = 0;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector2f phi(1e9f * (1 + 0.1f * normal(rng)), normal(rng));
    lmr.update(phi, phi.sum());
    ceilings += (lmr.covariance_guard() & kGuardCeiling) != 0;
  }
  EXPECT_GT(ceilings, 0);
  ASSERT_FALSE(lmr.failed());
  const Eigen::MatrixXf R = lmr.information();
  const float top = std::sqrt(std::numeric_limits<float>::max());
  EXPECT_LE(R(0, 0), top * 1.0001f);
  EXPECT_GT(R(0, 0), 0.5f * top);
  EXPECT_TRUE(R.allFinite());
  EXPECT_TRUE(lmr.P().allFinite());
  // The correlation of the two regressors (about 0) is kept.
  EXPECT_LT(std::abs(R(0, 1)) / std::sqrt(R(0, 0) * R(1, 1)), 0.1f);
}

// The step at compile-time size np against the same step at runtime size
// (one source, step_size.hpp: the unrolling and the local copies must not
// change the result) on the same regressors, step by step, np = 1..8,
// double and float: theta, the factor L and the prediction error to `tol`
// relative to their norms, the guard's action identical at every step. Three
// records: lambda = 0.98 with Gamma = 1e-2 I (one rank-one update per column of
// its root); lambda = 0.9 without Gamma and the regressors confined to one
// direction after 300 samples, so that R decays to the guard's floor in the
// others; lambda = 1 with regressors (and noise) of 1e9 (float) or 1e76
// (double), so that R's diagonal reaches the ceiling. (A first regressor alone
// that large made the prediction error, target - phi^T theta with |phi_1
// theta_1| = 1e76, the rounding of that product, which the other
// parameters then follow: the two paths parted completely in double, as
// any two orders of the sums would.) The step must not allocate.
struct LmrCounts {
  int repairs = 0, ceilings = 0;
};

template <typename S>
void expect_lmr_paths_agree(int np, int variant, double tol,
                            LmrCounts& total) {
  const char* names[3] = {"Gamma", "windup", "ceiling"};
  const std::string what = std::string("LMR-") + names[variant] +
                           " np = " + std::to_string(np) +
                           (sizeof(S) == 4 ? " float" : " double");
  const S lambda = variant == 0 ? S(0.98) : variant == 1 ? S(0.9) : S(1);
  const Matrix<S> gamma =
      variant == 0 ? Matrix<S>(S(1e-2) * Matrix<S>::Identity(np, np))
                   : Matrix<S>(Matrix<S>::Zero(np, np));
  const double big = sizeof(S) == 4 ? 1e9 : 1e76;
  LmrUpdate<S> fixed, dynamic;
  fixed.configure(np, lambda, gamma, true, true);
  dynamic.configure(np, lambda, gamma, true, false);
  EXPECT_EQ(fixed.fixed_size(), np) << what;
  EXPECT_EQ(dynamic.fixed_size(), 0) << what;
  const Matrix<S> P0 = S(10) * Matrix<S>::Identity(np, np);
  fixed.reset(Vector<S>::Zero(np), P0);
  dynamic.reset(Vector<S>::Zero(np), P0);
  std::mt19937 rng(60 + np + 10 * variant);
  std::normal_distribution<double> normal;
  const auto near = [&](const auto& a, const auto& b) {
    const Eigen::MatrixXd ad = a.template cast<double>();
    const Eigen::MatrixXd bd = b.template cast<double>();
    return (ad - bd).norm() <= tol * std::max(bd.norm(), 1e-300);
  };
  LmrCounts counts;
  long allocations = 0;
  Vector<S> phi(np);
  const int steps = variant == 1 ? 4000 : 1500;
  for (int k = 0; k < steps; ++k) {
    for (int i = 0; i < np; ++i) {
      double v = normal(rng);
      if (variant == 1 && k >= 300 && i > 0) v = 0;
      if (variant == 2) v *= big;
      phi(i) = S(v);
    }
    const double noise = 0.1 * normal(rng) * (variant == 2 ? big : 1.0);
    const S target = S(double(phi.sum()) + noise);
    const long before = g_allocations.load();
    const S error_fixed = fixed.update(phi, target);
    allocations += g_allocations.load() - before;
    const S error_dynamic = dynamic.update(phi, target);
    ASSERT_EQ(fixed.covariance_guard(), dynamic.covariance_guard())
        << what << ", step " << k;
    ASSERT_EQ(fixed.failed(), dynamic.failed()) << what << ", step " << k;
    counts.repairs += (dynamic.covariance_guard() & kGuardRepair) != 0;
    counts.ceilings += (dynamic.covariance_guard() & kGuardCeiling) != 0;
    ASSERT_TRUE(near(fixed.theta(), dynamic.theta()))
        << what << ", step " << k << ": relative difference "
        << (fixed.theta() - dynamic.theta()).norm() / dynamic.theta().norm();
    ASSERT_TRUE(near(fixed.factor(), dynamic.factor())) << what << ", " << k;
    // The error target - phi^T theta to the rounding of its terms (it
    // cancels: 1e72 out of terms of 1e76 in the ceiling record).
    const double terms = std::max(
        {1.0, std::abs(double(error_dynamic)), std::abs(double(target))});
    ASSERT_NEAR(double(error_fixed), double(error_dynamic), tol * terms)
        << what << ", step " << k;
  }
  EXPECT_FALSE(dynamic.failed()) << what;
  std::printf("%s: %d repairs, %d ceilings\n", what.c_str(), counts.repairs,
              counts.ceilings);
  EXPECT_EQ(allocations, 0) << what;
  total.repairs += counts.repairs;
  total.ceilings += counts.ceilings;
}

TEST(LmrUpdate, CompileTimeSizeStepAgreesWithRuntimeSize) {
  const double float_tol = 4500 * std::numeric_limits<float>::epsilon();
  LmrCounts total;
  for (int np = 1; np <= kMaxFixedParameters; ++np) {
    for (int variant = 0; variant < 3; ++variant) {
      expect_lmr_paths_agree<double>(np, variant, 1e-12, total);
      expect_lmr_paths_agree<float>(np, variant, float_tol, total);
    }
  }
  // The records make the guard act, so that identical actions mean
  // something.
  EXPECT_GE(total.repairs, 1);
  EXPECT_GE(total.ceilings, 1);
  LmrUpdate<double> large;
  large.configure(kMaxFixedParameters + 1, 1.0,
                  Eigen::MatrixXd::Zero(kMaxFixedParameters + 1,
                                        kMaxFixedParameters + 1),
                  true, true);
  EXPECT_EQ(large.fixed_size(), 0);
}

}  // namespace
}  // namespace ctid
