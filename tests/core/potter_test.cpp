// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/adaptation/potter.hpp (and condition_number in
// adaptation.hpp): the square-root filter PotterSVF, eq. (3.73), against the
// standard normalised Kalman filter, eq. (1.59); its behaviour in single
// precision on badly scaled regressors; no allocation per step.
#include "ctid/adaptation/potter.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <random>
#include <string>

#include "allocation_counter.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

// Uniform in [-1, 1) from the raw mt19937 stream (portable, unlike the
// standard distributions).
double uniform(std::mt19937& rng) {
  return static_cast<double>(rng()) / 2147483648.0 - 1.0;
}

Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937& rng) {
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform(rng);
  return v;
}

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

double smallest_eigenvalue(const Eigen::MatrixXd& P) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P,
                                                        Eigen::EigenvaluesOnly)
      .eigenvalues()(0);
}

struct Agreement {
  double theta = 0;  // max over steps of |theta_p - theta_kf| / |theta_kf|
  double P = 0;      // same for P in the Frobenius norm
  double error = 0;  // same for the prediction errors, relative to max|y|
};

// Runs the standard KF and PotterSVF in double on the same random
// regression (random-walk parameters, noisy target) and records how far
// apart they get.
// fixed_size: both on their fixed-size steps.
Agreement compare_with_kalman(const Eigen::MatrixXd& Qn, int steps,
                              unsigned seed, bool fixed_size = false) {
  const Eigen::Index np = Qn.rows();
  std::mt19937 rng(seed);
  ParameterUpdate<double> kf(np, KalmanAdaptation<double>(Qn), false,
                             fixed_size);
  PotterUpdate<double> potter(np, KalmanAdaptation<double>(Qn), fixed_size);
  EXPECT_EQ(kf.fixed_size(), fixed_size ? np : 0);
  EXPECT_EQ(potter.fixed_size(), fixed_size ? np : 0);
  const Eigen::VectorXd theta0 = random_vector(np, rng);
  const Eigen::MatrixXd P0 = 100 * Eigen::MatrixXd::Identity(np, np);
  kf.reset(theta0, P0);
  potter.reset(theta0, P0);
  Eigen::VectorXd theta_true = 3 * random_vector(np, rng);
  Agreement worst;
  for (int k = 0; k < steps; ++k) {
    theta_true += 0.01 * random_vector(np, rng);
    const Eigen::VectorXd phi = random_vector(np, rng);
    const double y = phi.dot(theta_true) + 0.1 * uniform(rng);
    const double e_kf = kf.update(phi, y);
    const double e_p = potter.update(phi, y);
    worst.error = std::max(worst.error, std::abs(e_kf - e_p) / 10);
    worst.theta =
        std::max(worst.theta, relative_difference(potter.theta(), kf.theta()));
    worst.P = std::max(worst.P, relative_difference(potter.P(), kf.P()));
  }
  return worst;
}

// Over 4000 steps the two forms differ by rounding only: measured (GCC,
// x86-64) at most theta 6.4e-15, P 1.2e-14, prediction error 3.3e-15 over
// the four runs below. 1e-10 leaves room for other compilers and kernels
// while still catching any algebraic slip (which shows at 1e-3 or more).
constexpr double kDoubleTolerance = 1e-10;

// Both forms dynamic, then both on their fixed-size steps.
TEST(PotterUpdate, AgreesWithStandardKalmanFilter) {
  std::mt19937 rng(1);
  Eigen::MatrixXd A(4, 4);
  for (int i = 0; i < 16; ++i) A(i) = uniform(rng);
  const Eigen::MatrixXd Qn = 1e-3 * A * A.transpose();
  for (const bool fixed : {false, true}) {
    const Agreement worst = compare_with_kalman(Qn, 4000, 2, fixed);
    EXPECT_LT(worst.theta, kDoubleTolerance) << test::scientific(worst.theta);
    EXPECT_LT(worst.P, kDoubleTolerance) << test::scientific(worst.P);
    EXPECT_LT(worst.error, kDoubleTolerance) << test::scientific(worst.error);
  }
}

TEST(PotterUpdate, AgreesWithRecursiveLeastSquaresWhenQnIsZero) {
  for (const bool fixed : {false, true}) {
    const Agreement worst =
        compare_with_kalman(Eigen::MatrixXd::Zero(3, 3), 4000, 3, fixed);
    EXPECT_LT(worst.theta, kDoubleTolerance) << test::scientific(worst.theta);
    EXPECT_LT(worst.P, kDoubleTolerance) << test::scientific(worst.P);
    EXPECT_LT(worst.error, kDoubleTolerance) << test::scientific(worst.error);
  }
}

// The step at compile-time size np against the same step at runtime size
// (one source, step_size.hpp: the unrolling and the local copies must not
// change the result) on the same regression, step by step, np = 1..8: Qn of
// full rank, Qn with a zero direction (a shorter QR stack), no Qn, and the
// forgetting factor form. theta, P = S S^T, the gain, beta and the prediction
// error to `tol` relative to their norms; the step must not allocate.
template <typename S>
void expect_potter_paths_agree(int np, int variant, double tol) {
  const char* names[4] = {"KF", "KF semi-definite Qn", "KF Qn = 0", "FF"};
  const std::string what = std::string("Potter-") + names[variant] +
                           " np = " + std::to_string(np) +
                           (sizeof(S) == 4 ? " float" : " double");
  std::mt19937 rng(40 + np + 10 * variant);
  Matrix<S> Qn = Matrix<S>::Zero(np, np);
  for (int i = 0; i < np; ++i) Qn(i, i) = S(1e-4 * (1 + i));
  if (variant == 1) Qn(0, 0) = 0;
  if (variant == 2) Qn.setZero();
  const Adaptation<S> adaptation =
      variant == 3 ? Adaptation<S>(ForgettingFactorAdaptation<S>(S(0.98)))
                   : Adaptation<S>(KalmanAdaptation<S>(Qn));
  PotterUpdate<S> fixed(np, adaptation, true);
  PotterUpdate<S> dynamic(np, adaptation, false);
  ASSERT_EQ(fixed.fixed_size(), np) << what;
  ASSERT_EQ(dynamic.fixed_size(), 0) << what;
  const Vector<S> theta0 = random_vector(np, rng).cast<S>();
  const Matrix<S> P0 = S(100) * Matrix<S>::Identity(np, np);
  fixed.reset(theta0, P0);
  dynamic.reset(theta0, P0);
  Vector<S> truth = (3 * random_vector(np, rng)).cast<S>();
  const auto near = [&](const auto& a, const auto& b) {
    const Eigen::MatrixXd ad = a.template cast<double>();
    const Eigen::MatrixXd bd = b.template cast<double>();
    return (ad - bd).norm() <= tol * std::max(bd.norm(), 1e-300);
  };
  long allocations = 0;
  for (int k = 0; k < 1500; ++k) {
    truth += (0.01 * random_vector(np, rng)).cast<S>();
    const Vector<S> phi = random_vector(np, rng).cast<S>();
    const S target = phi.dot(truth) + S(0.1 * uniform(rng));
    const long before = g_allocations.load();
    const S error_fixed = fixed.update(phi, target);
    allocations += g_allocations.load() - before;
    const S error_dynamic = dynamic.update(phi, target);
    ASSERT_TRUE(near(fixed.theta(), dynamic.theta())) << what << ", " << k;
    ASSERT_TRUE(near(fixed.P(), dynamic.P())) << what << ", step " << k;
    ASSERT_TRUE(near(fixed.gain(), dynamic.gain())) << what << ", " << k;
    ASSERT_NEAR(double(fixed.innovation_scale()),
                double(dynamic.innovation_scale()),
                tol * double(dynamic.innovation_scale()))
        << what << ", step " << k;
    ASSERT_NEAR(double(error_fixed), double(error_dynamic),
                tol * std::max(1.0, std::abs(double(error_dynamic))))
        << what << ", step " << k;
  }
  EXPECT_EQ(allocations, 0) << what;
}

TEST(PotterUpdate, CompileTimeSizeStepAgreesWithRuntimeSize) {
  const double float_tol = 4500 * std::numeric_limits<float>::epsilon();
  for (int np = 1; np <= kMaxFixedParameters; ++np) {
    for (int variant = 0; variant < 4; ++variant) {
      expect_potter_paths_agree<double>(np, variant, 1e-12);
      expect_potter_paths_agree<float>(np, variant, float_tol);
    }
  }
  PotterUpdate<double> large(kMaxFixedParameters + 1,
                             ForgettingFactorAdaptation<double>(1), true);
  EXPECT_EQ(large.fixed_size(), 0);
}

// The forgetting-factor form: S (I - f f^T / alpha) / sqrt(lambda) with
// beta = lambda + f^T f, alpha = beta + sqrt(lambda beta) reproduces the
// covariance form of eq. (1.57) step by step.
TEST(PotterUpdate, ForgettingFactorFormAgreesWithStandardRls) {
  std::mt19937 rng(11);
  const int np = 3;
  const double lambda = 0.95;
  ParameterUpdate<double> rls(np, ForgettingFactorAdaptation<double>(lambda));
  PotterUpdate<double> potter(np, ForgettingFactorAdaptation<double>(lambda));
  const Eigen::VectorXd theta0 = random_vector(np, rng);
  const Eigen::MatrixXd P0 = 10 * Eigen::MatrixXd::Identity(np, np);
  rls.reset(theta0, P0);
  potter.reset(theta0, P0);
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::VectorXd phi = random_vector(np, rng);
    const double target = uniform(rng);
    const double e1 = rls.update(phi, target);
    const double e2 = potter.update(phi, target);
    EXPECT_NEAR(e1, e2, 1e-9);
    EXPECT_NEAR(rls.innovation_scale(), potter.innovation_scale(),
                1e-9 * rls.innovation_scale());
    worst = std::max(worst, relative_difference(potter.P(), rls.P()));
  }
  EXPECT_LT(worst, kDoubleTolerance) << test::scientific(worst);
  EXPECT_LT(relative_difference(potter.theta(), rls.theta()), kDoubleTolerance);
  EXPECT_NEAR(potter.condition_number(), condition_number<double>(rls.P()),
              1e-6 * potter.condition_number());
}

TEST(PotterUpdate, EmptyQnMeansNoProcessNoise) {
  PotterUpdate<double> empty(2, KalmanAdaptation<double>());
  PotterUpdate<double> zero(
      2, KalmanAdaptation<double>(Eigen::MatrixXd::Zero(2, 2)));
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector2d phi(std::sin(0.3 * k), std::cos(0.7 * k));
    empty.update(phi, 1.0 + k);
    zero.update(phi, 1.0 + k);
  }
  EXPECT_TRUE(test::MatrixNear(empty.theta(), zero.theta(), 1e-15));
  EXPECT_TRUE(test::MatrixNear(empty.P(), zero.P(), 1e-15));
}

TEST(PotterUpdate, HandlesSemiDefiniteQn) {
  // The second parameter is known to be constant: zero row and column.
  Eigen::MatrixXd Qn = Eigen::MatrixXd::Zero(4, 4);
  Qn(0, 0) = 1e-3;
  Qn(2, 2) = 2e-3;
  Qn(3, 3) = 1e-4;
  Qn(2, 3) = Qn(3, 2) = 4e-4;
  const Agreement worst = compare_with_kalman(Qn, 4000, 4);
  EXPECT_LT(worst.theta, kDoubleTolerance) << test::scientific(worst.theta);
  EXPECT_LT(worst.P, kDoubleTolerance) << test::scientific(worst.P);
  EXPECT_LT(worst.error, kDoubleTolerance) << test::scientific(worst.error);

  // A rank-one Qn, not diagonal.
  const Eigen::Vector4d v(1, -2, 0.5, 3);
  const Agreement rank_one =
      compare_with_kalman(1e-4 * v * v.transpose(), 4000, 5);
  EXPECT_LT(rank_one.theta, kDoubleTolerance)
      << test::scientific(rank_one.theta);
  EXPECT_LT(rank_one.P, kDoubleTolerance) << test::scientific(rank_one.P);
}

TEST(PotterUpdate, SquareRootReproducesP) {
  const Eigen::Matrix3d Qn = Eigen::Vector3d(1e-2, 0, 1e-3).asDiagonal();
  PotterUpdate<double> potter(3, KalmanAdaptation<double>(Qn));
  for (int k = 0; k < 100; ++k) {
    potter.update(Eigen::Vector3d(std::sin(k), std::cos(2.0 * k), 1.0), 2.0);
  }
  const Eigen::MatrixXd& S = potter.sqrt_P();
  EXPECT_TRUE(
      test::MatrixNear(Eigen::MatrixXd(S * S.transpose()), potter.P(), 1e-15));
  EXPECT_TRUE(potter.P().isApprox(potter.P().transpose(), 0));
}

TEST(PotterUpdate, SemidefiniteSquareRoot) {
  const Eigen::Vector3d v(1, 2, -1);
  const Eigen::MatrixXd M = v * v.transpose() + Eigen::Vector3d(0, 1, 1) *
                                                    Eigen::RowVector3d(0, 1, 1);
  const Eigen::MatrixXd R = semidefinite_square_root<double>(M);
  EXPECT_EQ(R.cols(), 2);
  EXPECT_TRUE(test::MatrixNear(Eigen::MatrixXd(R * R.transpose()), M, 1e-14));
  EXPECT_EQ(
      semidefinite_square_root<double>(Eigen::MatrixXd::Zero(3, 3)).cols(), 0);
}

TEST(PotterUpdate, UpdateDoesNotAllocate) {
  Eigen::MatrixXd Qn = 1e-4 * Eigen::MatrixXd::Identity(5, 5);
  Qn(1, 1) = 0;
  PotterUpdate<double> potter(5, KalmanAdaptation<double>(Qn));
  Eigen::VectorXd phi(5);
  const long before = g_allocations.load();
  double sum = 0;
  for (int k = 0; k < 10000; ++k) {
    for (int i = 0; i < 5; ++i) phi(i) = std::sin(0.1 * k * (i + 1));
    sum += potter.update(phi, std::cos(0.2 * k));
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
}

// Single precision on regressors of very different scale (1e3, 1, 1e-3),
// P0 = 1e6 I, Qn = 1e-6 I, 4000 steps, eight seeds. The double reference
// ends with kappa_2(P) = 3.5e8 to 1.4e9, beyond 1/eps_float = 1.7e7.
// Measured (GCC, x86-64):
//   standard KF, float: P indefinite (smallest eigenvalue down to -1e5) in
//     the first 1-3 steps for 5 of the 8 seeds, where P0 = 1e6 I meets
//     |phi_1| ~ 1e3 and P11 is the difference of two numbers ~1e6;
//     final ||dP||/||P|| 2e-6 to 8.4e-4 (mean 1.9e-4), ||dtheta||/||theta||
//     5.6e-5 to 3.7e-2 (mean 8.3e-3);
//   PotterSVF, float: P positive definite at every step of every seed
//     (smallest eigenvalue ~6.3e-7); final ||dP||/||P|| 6.8e-7 to 8.8e-6
//     (mean 3.6e-6), ||dtheta||/||theta|| 6.4e-6 to 2.8e-4 (mean 1.3e-4).
// Seed by seed the standard KF is not always worse (seed 5: theta 5.6e-5 vs
// 1.8e-4), so the assertions are on definiteness and on the means, with
// margins of 3x or more on the measured values.
struct FloatRun {
  double kappa_double = 0;    // kappa_2(P) at the end, double reference
  double min_eig_kf = 1e300;  // smallest eigenvalue of P over the run
  double min_eig_potter = 1e300;
  int indefinite_steps_kf = 0;  // steps with P not positive definite
  int indefinite_steps_potter = 0;
  double P_error_kf = 0;  // final ||P_float - P_double||_F / ||P_double||_F
  double P_error_potter = 0;
  double theta_error_kf = 0;  // final relative theta error vs double
  double theta_error_potter = 0;
};

FloatRun run_badly_scaled(unsigned seed) {
  const int np = 3;
  const Eigen::Vector3d scale(1e3, 1, 1e-3);
  const Eigen::Vector3d theta_true(1, 2, 3);
  const Eigen::MatrixXd Qn = 1e-6 * Eigen::MatrixXd::Identity(np, np);
  const Eigen::MatrixXd P0 = 1e6 * Eigen::MatrixXd::Identity(np, np);
  ParameterUpdate<double> reference(np, KalmanAdaptation<double>(Qn));
  ParameterUpdate<float> kf(np, KalmanAdaptation<float>(Qn.cast<float>()));
  PotterUpdate<float> potter(np, KalmanAdaptation<float>(Qn.cast<float>()));
  reference.reset(Eigen::VectorXd::Zero(np), P0);
  kf.reset(Eigen::VectorXf::Zero(np), P0.cast<float>());
  potter.reset(Eigen::VectorXf::Zero(np), P0.cast<float>());
  std::mt19937 rng(seed);
  FloatRun run;
  for (int k = 0; k < 4000; ++k) {
    const Eigen::Vector3d phi = scale.cwiseProduct(random_vector(np, rng));
    const double y = phi.dot(theta_true) + 0.1 * uniform(rng);
    reference.update(phi, y);
    kf.update(phi.cast<float>(), static_cast<float>(y));
    potter.update(phi.cast<float>(), static_cast<float>(y));
    const double eig_kf = smallest_eigenvalue(kf.P().cast<double>());
    const double eig_potter = smallest_eigenvalue(potter.P().cast<double>());
    run.min_eig_kf = std::min(run.min_eig_kf, eig_kf);
    run.min_eig_potter = std::min(run.min_eig_potter, eig_potter);
    run.indefinite_steps_kf += !(eig_kf > 0);
    run.indefinite_steps_potter += !(eig_potter > 0);
  }
  run.kappa_double = condition_number<double>(reference.P());
  run.P_error_kf = relative_difference(kf.P().cast<double>(), reference.P());
  run.P_error_potter =
      relative_difference(potter.P().cast<double>(), reference.P());
  run.theta_error_kf =
      relative_difference(kf.theta().cast<double>(), reference.theta());
  run.theta_error_potter =
      relative_difference(potter.theta().cast<double>(), reference.theta());
  return run;
}

TEST(PotterUpdate, SinglePrecisionOnBadlyScaledRegressors) {
  constexpr int kSeeds = 8;
  int kf_indefinite_runs = 0;
  double P_error_kf = 0, P_error_potter = 0;
  double theta_error_kf = 0, theta_error_potter = 0;
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    const FloatRun run = run_badly_scaled(seed);
    std::printf(
        "seed %u: kappa(P) %.2e | min eig KF %.2e Potter %.2e | indefinite "
        "steps KF %d Potter %d | P err KF %.2e Potter %.2e | theta err KF "
        "%.2e Potter %.2e\n",
        seed, run.kappa_double, run.min_eig_kf, run.min_eig_potter,
        run.indefinite_steps_kf, run.indefinite_steps_potter, run.P_error_kf,
        run.P_error_potter, run.theta_error_kf, run.theta_error_potter);
    EXPECT_EQ(run.indefinite_steps_potter, 0) << "seed " << seed;
    EXPECT_GT(run.min_eig_potter, 0) << "seed " << seed;
    EXPECT_LT(run.theta_error_potter, 1e-3) << "seed " << seed;
    EXPECT_LT(run.P_error_potter, 1e-4) << "seed " << seed;
    kf_indefinite_runs += run.indefinite_steps_kf > 0;
    P_error_kf += run.P_error_kf / kSeeds;
    P_error_potter += run.P_error_potter / kSeeds;
    theta_error_kf += run.theta_error_kf / kSeeds;
    theta_error_potter += run.theta_error_potter / kSeeds;
  }
  EXPECT_GE(kf_indefinite_runs, 2);
  EXPECT_GT(P_error_kf, 10 * P_error_potter)
      << test::scientific(P_error_kf) << " vs "
      << test::scientific(P_error_potter);
  EXPECT_GT(theta_error_kf, 10 * theta_error_potter)
      << test::scientific(theta_error_kf) << " vs "
      << test::scientific(theta_error_potter);
}

TEST(ConditionNumber, KnownMatrix) {
  // P = Q diag(2, 50, 2e4) Q^T with Q a rotation: kappa_2 = 1e4.
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  const Eigen::MatrixXd P =
      Q * Eigen::Vector3d(2, 50, 2e4).asDiagonal() * Q.transpose();
  EXPECT_NEAR(condition_number<double>(P), 1e4, 1e4 * 1e-12);
  EXPECT_DOUBLE_EQ(condition_number<double>(Eigen::MatrixXd::Identity(4, 4)),
                   1.0);
  const Eigen::MatrixXd singular =
      Eigen::Vector2d(1, 1) * Eigen::RowVector2d(1, 1);
  EXPECT_TRUE(std::isinf(condition_number<double>(singular)));
}

TEST(ConditionNumber, FromSquareRootIsTheSquareOfKappaS) {
  // eq. (3.68): kappa_2(S S^T) = kappa_2(S)^2.
  const Eigen::Matrix3d S =
      (Eigen::Matrix3d() << 3, 0, 0, 1, 0.2, 0, -2, 0.5, 0.01).finished();
  const double kappa_P = condition_number<double>(S * S.transpose());
  EXPECT_NEAR(condition_number_from_square_root<double>(S), kappa_P,
              kappa_P * 1e-8);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(S);
  const double kappa_S = svd.singularValues()(0) / svd.singularValues()(2);
  EXPECT_NEAR(kappa_P, kappa_S * kappa_S, kappa_P * 1e-8);
}

}  // namespace
}  // namespace ctid
