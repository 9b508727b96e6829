// Tests of core/include/ctid/covariance_guard.hpp: the floor on the
// symmetric part of P and the ceiling on its trace, on matrices with known
// eigenvalues, and a long run (10^6 samples, CTID_LONG_RUN_SAMPLES to
// change it) under poor excitation of every recursive estimator in double
// and single precision, after which P must be finite with a positive
// definite symmetric part at every check (bench/long_run_bench.cpp runs the
// same for 10^8 samples).
#include "ctid/covariance_guard.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "long_run_scenario.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

TEST(CovarianceGuard, LeavesAPositiveDefiniteMatrixUntouched) {
  CovarianceGuard<double> guard;
  guard.configure(3, 0);
  Eigen::MatrixXd P(3, 3);
  // Non-symmetric; Ps = [4 .35 0; .35 3 0; 0 0 1e-6] positive definite.
  P << 4, 1, 0.5, -0.3, 3, 0.2, -0.5, -0.2, 1e-6;
  const Eigen::MatrixXd before = P;
  EXPECT_EQ(guard.apply(P), kGuardNone);
  EXPECT_TRUE((P.array() == before.array()).all());
}

TEST(CovarianceGuard, RaisesTheEigenvaluesOfAnIndefiniteSymmetricPart) {
  CovarianceGuard<double> guard;
  guard.configure(3, 0);
  // Ps = Q diag(5, 1, -1e-3) Q^T plus an antisymmetric part.
  const Eigen::MatrixXd Q =
      Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(3, 3))
          .householderQ();
  const Eigen::Vector3d lambda(5, 1, -1e-3);
  Eigen::MatrixXd K(3, 3);
  K << 0, 0.2, -0.1, -0.2, 0, 0.3, 0.1, -0.3, 0;
  Eigen::MatrixXd P = Q * lambda.asDiagonal() * Q.transpose() + K;
  const double norm_before = ((P + P.transpose()) / 2).norm();
  EXPECT_EQ(guard.apply(P), kGuardFloor);
  // Symmetric, the positive eigenvalues and eigenvectors kept, the
  // negative one raised to the floor rho trace(Ps), rho = 3 eps.
  EXPECT_TRUE(P.isApprox(P.transpose(), 0));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(P);
  const double floor = 3 * std::numeric_limits<double>::epsilon() * 5.999;
  EXPECT_NEAR(eig.eigenvalues()(0), floor, 1e-12 * 5);
  EXPECT_NEAR(eig.eigenvalues()(1), 1, 1e-12 * 5);
  EXPECT_NEAR(eig.eigenvalues()(2), 5, 1e-12 * 5);
  EXPECT_LE(P.norm(), norm_before * (1 + 1e-12));
  EXPECT_TRUE(long_run::symmetric_part_definite<double>(P));
}

TEST(CovarianceGuard, ScalesATraceAboveTheCeiling) {
  CovarianceGuard<float> guard;
  guard.configure(2, 10);
  Eigen::MatrixXf P(2, 2);
  P << 30, 1, 1, 10;
  EXPECT_EQ(guard.apply(P), kGuardCeiling);
  EXPECT_NEAR(P.trace(), 10, 1e-5 * 10);
  EXPECT_NEAR(P(0, 0) / P(1, 1), 3, 1e-6 * 3);
  Eigen::MatrixXf Q(2, 2);
  Q << 3, 0, 0, 2;
  EXPECT_EQ(guard.apply(Q), kGuardNone);
}

TEST(CovarianceGuard, LeavesNonFiniteMatricesToTheRunCheck) {
  CovarianceGuard<double> guard;
  guard.configure(2, 1);
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(2, 2);
  P(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(guard.apply(P), kGuardNone);
}

long long_run_samples() {
  const char* env = std::getenv("CTID_LONG_RUN_SAMPLES");
  return env != nullptr ? std::atol(env) : 1000000L;
}

template <typename S>
void check_long_runs() {
  const long n = long_run_samples();
  for (const auto& c : long_run::cases<S>(n)) {
    const long_run::Result r = c.run(n, 1000);
    EXPECT_EQ(r.first_nonfinite, -1)
        << c.name << ": P or theta not finite at sample " << r.first_nonfinite;
    EXPECT_EQ(r.first_indefinite, -1)
        << c.name << ": symmetric part of P indefinite at sample "
        << r.first_indefinite;
    EXPECT_GT(r.min_relative_eig, 0) << c.name;
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
