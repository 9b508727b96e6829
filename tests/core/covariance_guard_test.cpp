// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/adaptation/covariance_guard.hpp: P left alone bit for
// bit while its symmetric part is positive definite, however badly scaled;
// an indefinite symmetric part repaired in correlation form with the
// antisymmetric part kept, the same way in any units; the ceiling as a
// congruence; no allocation; fixed and dynamic sizes alike. Then the long
// run (10^6 samples, CTID_LONG_RUN_SAMPLES to change it) under poor
// excitation of every recursive estimator in double and single precision:
// P finite with a positive definite symmetric part at every sample
// (Cholesky; for LMR P = R^-1 formed from R's factor, lmr.hpp; see
// long_run_scenario.hpp for the IV estimators with a forgetting factor
// < 1); bench/long_run_bench.cpp runs the same for 10^8 samples.
#include "ctid/adaptation/covariance_guard.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "allocation_counter.hpp"
#include "long_run_scenario.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

// A random correlation-type matrix Q diag(lambda) Q^T.
Eigen::MatrixXd with_eigenvalues(const Eigen::VectorXd& lambda, int seed) {
  std::srand(seed);
  const Eigen::Index n = lambda.size();
  const Eigen::MatrixXd Q =
      Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n))
          .householderQ();
  return Q * lambda.asDiagonal() * Q.transpose();
}

Eigen::MatrixXd antisymmetric(Eigen::Index n, double size) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Random(n, n) * size;
  return (K - K.transpose()) / 2;
}

bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a.array() == b.array()).all();
}

TEST(CovarianceGuard, LeavesAPositiveDefiniteMatrixUntouched) {
  CovarianceGuard<double> guard;
  guard.configure(3, true);
  Eigen::MatrixXd P(3, 3);
  // Non-symmetric; Ps = [4 .35 0; .35 3 0; 0 0 1e-6] positive definite.
  P << 4, 1, 0.5, -0.3, 3, 0.2, -0.5, -0.2, 1e-6;
  const Eigen::MatrixXd before = P;
  for (int k = 0; k < 10; ++k) EXPECT_EQ(guard.apply(P), kGuardNone);
  EXPECT_TRUE(same_bits(P, before));
}

// The case that broke the trace-relative floor: P0 = diag(1e4 .. 1e20)
// (thesis sec. 4.1), kappa_2(P) = 1e16, but well conditioned in
// correlation form.
TEST(CovarianceGuard, LeavesABadlyScaledPositiveDefiniteMatrixUntouched) {
  for (const double spread : {1e16, 1e30}) {
    CovarianceGuard<double> guard;
    guard.configure(4, true);
    Eigen::Vector4d d;
    d << 1e2, 1e2 * std::pow(spread, 1.0 / 6), 1e2 * std::pow(spread, 1.0 / 3),
        1e2 * std::sqrt(spread);
    const Eigen::MatrixXd C =
        with_eigenvalues(Eigen::Vector4d(0.01, 0.5, 1.2, 2.29), 3);
    Eigen::MatrixXd P = d.asDiagonal() * C * d.asDiagonal();
    P += d.asDiagonal() * antisymmetric(4, 0.05) * d.asDiagonal();
    const Eigen::MatrixXd before = P;
    EXPECT_EQ(guard.apply(P), kGuardNone) << "spread " << spread;
    EXPECT_TRUE(same_bits(P, before));
  }
}

TEST(CovarianceGuard, RepairsAnIndefiniteSymmetricPartKeepingTheRest) {
  CovarianceGuard<double> guard;
  guard.configure(3, true);
  const Eigen::MatrixXd Ps =
      with_eigenvalues(Eigen::Vector3d(-1e-3, 1, 2), 5);
  const Eigen::MatrixXd K = antisymmetric(3, 0.1);
  Eigen::MatrixXd P = Ps + K;
  ASSERT_FALSE(long_run::symmetric_part_definite<double>(P));
  EXPECT_EQ(guard.apply(P), kGuardRepair);
  // The antisymmetric part is kept exactly, the symmetric part is
  // positive definite, and the correction is rank one (one eigenvalue of
  // the correlation form raised).
  EXPECT_TRUE(test::MatrixNear((P - P.transpose()) / 2, K, 1e-15));
  EXPECT_TRUE(long_run::symmetric_part_definite<double>(P));
  const Eigen::MatrixXd change = (P + P.transpose()) / 2 - Ps;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(change);
  EXPECT_NEAR(eig.eigenvalues()(0), 0, 1e-14);
  EXPECT_NEAR(eig.eigenvalues()(1), 0, 1e-14);
  EXPECT_GT(eig.eigenvalues()(2), 1e-3);
  // The raised eigenvalue of C sits at the floor 10 n eps lambda_max(C).
  const Eigen::Vector3d d = P.diagonal().cwiseSqrt();
  const Eigen::MatrixXd C = d.cwiseInverse().asDiagonal() *
                            ((P + P.transpose()) / 2) *
                            d.cwiseInverse().asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ceig(C);
  const double floor = 10 * 3 * std::numeric_limits<double>::epsilon();
  EXPECT_GT(ceig.eigenvalues()(0), 0.5 * floor);
  EXPECT_LT(ceig.eigenvalues()(0), 2 * floor * ceig.eigenvalues()(2));
  // Repaired once, it passes the next test.
  EXPECT_EQ(guard.apply(P), kGuardNone);
}

// Units of the parameters do not matter: guarding D0 P D0 gives D0 times
// the guarded P times D0.
TEST(CovarianceGuard, RepairIsScaleInvariant) {
  CovarianceGuard<double> guard;
  guard.configure(3, true);
  const Eigen::MatrixXd P =
      with_eigenvalues(Eigen::Vector3d(-1e-2, 0.7, 2), 9) +
      antisymmetric(3, 0.2);
  Eigen::MatrixXd A = P;
  EXPECT_EQ(guard.apply(A), kGuardRepair);
  const Eigen::Vector3d d0(1e-6, 1, 1e9);
  Eigen::MatrixXd B = d0.asDiagonal() * P * d0.asDiagonal();
  EXPECT_EQ(guard.apply(B), kGuardRepair);
  const Eigen::MatrixXd back =
      d0.cwiseInverse().asDiagonal() * B * d0.cwiseInverse().asDiagonal();
  EXPECT_TRUE(test::MatrixNear(back, A, 1e-12));
}

TEST(CovarianceGuard, RepairsANonPositiveVariance) {
  CovarianceGuard<double> guard;
  guard.configure(2, true);
  Eigen::MatrixXd P(2, 2);
  P << 1e6, 10, 10, -1e-3;
  EXPECT_EQ(guard.apply(P), kGuardRepair);
  EXPECT_TRUE(long_run::symmetric_part_definite<double>(P));
  P << 1e6, 0, 0, 0;
  EXPECT_EQ(guard.apply(P), kGuardRepair);
  EXPECT_TRUE(long_run::symmetric_part_definite<double>(P));
}

TEST(CovarianceGuard, CeilingIsACongruenceAtTheRangeOfThePrecision) {
  CovarianceGuard<float> guard;
  guard.configure(2, true);
  Eigen::MatrixXf P0 = Eigen::MatrixXf::Identity(2, 2) * 1e4f;
  guard.reset(P0);
  const float top = std::sqrt(std::numeric_limits<float>::max());
  Eigen::MatrixXf P(2, 2);
  P << 1e30f, 1e14f, 1e14f, 1.0f;  // correlation 0.1
  EXPECT_EQ(guard.apply(P), kGuardCeiling);
  EXPECT_NEAR(P(0, 0) / top, 1, 1e-5);
  EXPECT_EQ(P(1, 1), 1.0f);
  EXPECT_NEAR(P(0, 1) / std::sqrt(P(0, 0) * P(1, 1)), 0.1, 1e-5);
  // A P0 above the range keeps its variances.
  P0(0, 0) = 1e25f;
  guard.reset(P0);
  P << 1e25f, 0, 0, 1;
  EXPECT_EQ(guard.apply(P), kGuardNone);
}

TEST(CovarianceGuard, DisabledDoesNothing) {
  CovarianceGuard<double> guard;
  guard.configure(2, false);
  Eigen::MatrixXd P(2, 2);
  P << 1, 2, 2, 1;
  EXPECT_EQ(guard.apply(P), kGuardNone);
  EXPECT_EQ(P(0, 1), 2);
}

TEST(CovarianceGuard, LeavesNonFiniteMatricesToTheRunCheck) {
  CovarianceGuard<double> guard;
  guard.configure(2, true);
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(2, 2);
  P(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(guard.apply(P), kGuardNone);
}

TEST(CovarianceGuard, NoAllocationAndFixedSizeAlike) {
  CovarianceGuard<double> dynamic, fixed;
  dynamic.configure(3, true);
  fixed.configure(3, true);
  const Eigen::MatrixXd bad =
      with_eigenvalues(Eigen::Vector3d(-1e-3, 1, 2), 5) + antisymmetric(3, 0.1);
  Eigen::MatrixXd a = bad;
  Eigen::Matrix3d b = bad;
  const long before = g_allocations.load();
  EXPECT_EQ(dynamic.apply(a), kGuardRepair);
  const double* values = b.data();
  EXPECT_EQ((fixed.apply_step<3, false>(values, b.data())), kGuardRepair);
  EXPECT_EQ(dynamic.apply(a), kGuardNone);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(test::MatrixNear(a, Eigen::MatrixXd(b), 1e-15));
}

// apply_step<K, true> (the test at compile-time size K on a local copy of
// P, as the least-squares step calls it, reading P(i, j) for the
// symmetric part) against apply() at runtime size, which forms (P(i, j) +
// P(j, i)) / 2, on the same exactly symmetric matrices, K = 1..8:
// positive definite ones from well to barely conditioned (smallest
// eigenvalue of the correlation form around the detection level rho =
// n eps), indefinite ones, a variance that is zero, negative, NaN or above
// the ceiling, an off-diagonal entry above max / 2. The same action at
// every call and the same P bit for bit, over two calls in a row (the
// counters carry over).
template <int K>
void expect_symmetric_test_matches_apply() {
  using Mat = Eigen::Matrix<double, K, K>;
  const double eps = std::numeric_limits<double>::epsilon();
  int acted = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(K, 1, 2);
    const int kind = trial % 10;
    // The smallest eigenvalue from comfortable to the detection level
    // rho = K eps and below it, then negative.
    const double smallest[7] = {1,       1e-6,         1e-10,  1e3 * K * eps,
                                K * eps, 0.5 * K * eps, -1e-10};
    if (kind <= 6) lambda(0) = smallest[kind];
    Eigen::MatrixXd C = with_eigenvalues(lambda, 700 + trial);
    C = (C + C.transpose()).eval() / 2;  // exactly symmetric
    Eigen::VectorXd scales = Eigen::VectorXd::LinSpaced(K, 0, 8 * (trial % 3));
    for (int i = 0; i < K; ++i) scales(i) = std::pow(10.0, scales(i));
    Mat P = scales.asDiagonal() * C * scales.asDiagonal();
    for (int j = 0; j < K; ++j) {
      for (int i = 0; i < j; ++i) P(i, j) = P(j, i);
    }
    const int last = K - 1;
    if (kind == 7) P(last, last) = trial % 2 ? 0.0 : -1.0;
    if (kind == 8) {
      P(last, last) =
          trial % 4 == 0 ? std::numeric_limits<double>::quiet_NaN() : 1e160;
    }
    if (kind == 9 && K > 1) {
      P(last, 0) = P(0, last) = 1e308;
      P(0, 0) = P(last, last) = 1e300;
    }
    CovarianceGuard<double> dynamic, fixed;
    dynamic.configure(K, true);
    fixed.configure(K, true);
    if (kind == 9) {  // a ceiling of 1e300, raised by P(t_0)
      dynamic.reset(P);
      fixed.reset(P);
    }
    Eigen::MatrixXd a = P;
    Mat b = P;
    for (int call = 0; call < 2; ++call) {
      double p[K * K];
      for (int j = 0; j < K; ++j) {
        for (int i = 0; i < K; ++i) p[j * K + i] = b(i, j);
      }
      if (!(b == b.transpose())) break;  // a repair may leave it asymmetric
      const int expected = dynamic.apply(a);
      const int got = fixed.apply_step<K, true>(p, b.data());
      acted += expected != kGuardNone;
      ASSERT_EQ(got, expected) << "K = " << K << ", trial " << trial;
      const Eigen::MatrixXd bd = b;
      ASSERT_TRUE((a.array() == bd.array() ||
                   (a.array().isNaN() && bd.array().isNaN()))
                      .all())
          << "K = " << K << ", trial " << trial;
    }
  }
  EXPECT_GE(acted, 10) << "K = " << K << ": the cases never made it act";
}

TEST(CovarianceGuard, UnrolledSymmetricTestDecidesAsApply) {
  expect_symmetric_test_matches_apply<1>();
  expect_symmetric_test_matches_apply<2>();
  expect_symmetric_test_matches_apply<3>();
  expect_symmetric_test_matches_apply<4>();
  expect_symmetric_test_matches_apply<5>();
  expect_symmetric_test_matches_apply<6>();
  expect_symmetric_test_matches_apply<7>();
  expect_symmetric_test_matches_apply<8>();
}

// apply_step<K, false> (the test at compile-time size K on a local copy of
// P, as the IV step calls it, whose P is not symmetric) against apply() at
// runtime size on the same matrices, K = 1..8, double
// and float: a symmetric part from well conditioned to barely and not
// positive definite (its smallest eigenvalue around the detection level
// rho = n eps and below), an antisymmetric part from none to as large as
// the symmetric one, variances over 16 decades, a variance that is zero,
// negative, NaN or above the ceiling. The same action at every call and
// the same P bit for bit, over two calls in a row (the counters carry
// over, a repaired P is tested again).
template <typename S, int K>
void expect_unrolled_test_matches_apply() {
  using Mat = Eigen::Matrix<S, K, K>;
  const double eps = std::numeric_limits<S>::epsilon();
  int acted = 0;
  for (int trial = 0; trial < 80; ++trial) {
    Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(K, 1, 2);
    const int kind = trial % 10;
    const double smallest[7] = {1,       1e-3,          1e-6, 1e3 * K * eps,
                                K * eps, 0.5 * K * eps, -1e-4};
    if (kind <= 6) lambda(0) = smallest[kind];
    Eigen::MatrixXd C = with_eigenvalues(lambda, 900 + trial);
    C = (C + C.transpose()).eval() / 2;
    const double skew[4] = {0, 1e-6, 0.1, 1};
    C += antisymmetric(K, skew[trial % 4]);
    Eigen::VectorXd scales = Eigen::VectorXd::LinSpaced(K, 0, 4 * (trial % 3));
    for (int i = 0; i < K; ++i) scales(i) = std::pow(10.0, scales(i));
    Mat P = (scales.asDiagonal() * C * scales.asDiagonal()).cast<S>();
    const int last = K - 1;
    if (kind == 7) P(last, last) = trial % 2 ? S(0) : S(-1);
    if (kind == 8) {
      P(last, last) = trial % 4 == 0 ? std::numeric_limits<S>::quiet_NaN()
                                     : S(2) * std::sqrt(std::numeric_limits<
                                                        S>::max());
    }
    CovarianceGuard<S> dynamic, fixed;
    dynamic.configure(K, true);
    fixed.configure(K, true);
    Matrix<S> a = P;
    Mat b = P;
    for (int call = 0; call < 2; ++call) {
      S p[K * K];
      for (int j = 0; j < K; ++j) {
        for (int i = 0; i < K; ++i) p[j * K + i] = b(i, j);
      }
      const int expected = dynamic.apply(a);
      const int got = fixed.template apply_step<K, false>(p, b.data());
      acted += expected != kGuardNone;
      ASSERT_EQ(got, expected) << "K = " << K << ", trial " << trial;
      const Matrix<S> bd = b;
      ASSERT_TRUE((a.array() == bd.array() ||
                   (a.array().isNaN() && bd.array().isNaN()))
                      .all())
          << "K = " << K << ", trial " << trial;
    }
  }
  EXPECT_GE(acted, 10) << "K = " << K << ": the cases never made it act";
}

template <typename S>
void expect_unrolled_tests_match_apply() {
  expect_unrolled_test_matches_apply<S, 1>();
  expect_unrolled_test_matches_apply<S, 2>();
  expect_unrolled_test_matches_apply<S, 3>();
  expect_unrolled_test_matches_apply<S, 4>();
  expect_unrolled_test_matches_apply<S, 5>();
  expect_unrolled_test_matches_apply<S, 6>();
  expect_unrolled_test_matches_apply<S, 7>();
  expect_unrolled_test_matches_apply<S, 8>();
}

TEST(CovarianceGuard, UnrolledGeneralTestDecidesAsApply) {
  expect_unrolled_tests_match_apply<double>();
  expect_unrolled_tests_match_apply<float>();
}

// A short run (20 s excited, 180 s constant) is not touched: every
// estimator gives the same bits with and without the guard (the thesis
// reproductions depend on it).
TEST(CovarianceGuard, ShortRunsAreBitIdentical) {
  for (const auto& c : long_run::cases<double>(20000)) {
    const long_run::Result on = c.run(20000, 1, true);
    const long_run::Result off = c.run(20000, 1, false);
    EXPECT_EQ(on.guard_actions, 0) << c.name;
    EXPECT_TRUE((on.theta_end.array() == off.theta_end.array()).all())
        << c.name;
  }
}

long long_run_samples() {
  const char* env = std::getenv("CTID_LONG_RUN_SAMPLES");
  return env != nullptr ? std::atol(env) : 1000000L;
}

template <typename S>
void check_long_runs() {
  const long n = long_run_samples();
  for (const auto& c : long_run::cases<S>(n)) {
    const long_run::Result r = c.run(n, 1, true);
    EXPECT_EQ(r.first_nonfinite, -1)
        << c.name << ": P or theta not finite at sample " << r.first_nonfinite;
    EXPECT_EQ(r.first_indefinite, -1)
        << c.name << ": symmetric part of P indefinite at sample "
        << r.first_indefinite << " (" << r.indefinite_checks << " samples)";
    std::printf("  %-18s guard acted at %ld samples (first %ld), "
                "min eig ratio %.3g\n",
                c.name.c_str(), r.guard_actions, r.first_guard,
                r.min_relative_eig);
  }
}

TEST(CovarianceGuardLongRun, EveryEstimatorKeepsPDefiniteInDouble) {
  check_long_runs<double>();
}

TEST(CovarianceGuardLongRun, EveryEstimatorKeepsPDefiniteInSingle) {
  check_long_runs<float>();
}

}  // namespace
}  // namespace ctid
