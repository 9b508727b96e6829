// Tests of core/include/ctid/adaptation/adaptation.hpp: the recursive updates against
// their batch (information-form) solutions.
#include "ctid/adaptation/adaptation.hpp"

#include <gtest/gtest.h>

#include <random>

#include "test_util.hpp"

namespace ctid {
namespace {

struct Regression {
  Eigen::MatrixXd phi;   // N-by-np
  Eigen::MatrixXd zeta;  // instruments
  Eigen::VectorXd y;
};

Regression make_regression(int n, int np, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Regression r;
  r.phi.resize(n, np);
  r.zeta.resize(n, np);
  r.y.resize(n);
  Eigen::VectorXd theta(np);
  for (int i = 0; i < np; ++i) theta(i) = normal(rng);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < np; ++i) {
      r.phi(k, i) = normal(rng);
      r.zeta(k, i) = r.phi(k, i) + 0.5 * normal(rng);
    }
    r.y(k) = r.phi.row(k).dot(theta) + 0.3 * normal(rng);
  }
  return r;
}

// Exponentially weighted, regularised least squares:
//   min sum_k lambda^(N-k) (y_k - phi_k theta)^2
//       + lambda^N (theta - theta0)^T P0^-1 (theta - theta0)
// solved by QR of the weighted, stacked system.
Eigen::VectorXd weighted_batch(const Regression& r, double lambda,
                               const Eigen::VectorXd& theta0,
                               const Eigen::MatrixXd& P0) {
  const int n = r.phi.rows(), np = r.phi.cols();
  Eigen::MatrixXd A(n + np, np);
  Eigen::VectorXd b(n + np);
  for (int k = 0; k < n; ++k) {
    const double w = std::sqrt(std::pow(lambda, n - 1 - k));
    A.row(k) = w * r.phi.row(k);
    b(k) = w * r.y(k);
  }
  const Eigen::MatrixXd root =
      Eigen::LLT<Eigen::MatrixXd>(P0.inverse()).matrixU();
  const double w0 = std::sqrt(std::pow(lambda, n));
  A.bottomRows(np) = w0 * root;
  b.tail(np) = w0 * root * theta0;
  return A.colPivHouseholderQr().solve(b);
}

TEST(ParameterUpdate, RlsWithUnitForgettingEqualsBatchLeastSquares) {
  const int np = 4;
  const Regression r = make_regression(300, np, 1);
  const Eigen::VectorXd theta0 = Eigen::VectorXd::Constant(np, 0.2);
  const Eigen::MatrixXd P0 = 100 * Eigen::MatrixXd::Identity(np, np);
  ParameterUpdate<double> update(np, ForgettingFactorAdaptation<double>(1.0));
  update.reset(theta0, P0);
  for (int k = 0; k < r.phi.rows(); ++k) {
    update.update(r.phi.row(k).transpose(), r.y(k));
  }
  const Eigen::VectorXd batch = weighted_batch(r, 1.0, theta0, P0);
  EXPECT_LT(test::relative_error(update.theta(), batch), 1e-9);
}

TEST(ParameterUpdate, ForgettingFactorEqualsExponentiallyWeightedBatch) {
  const int np = 3;
  const Regression r = make_regression(200, np, 2);
  const Eigen::VectorXd theta0 = Eigen::VectorXd::Zero(np);
  const Eigen::MatrixXd P0 = 1e3 * Eigen::MatrixXd::Identity(np, np);
  const double lambda = 0.97;
  ParameterUpdate<double> update(np,
                                 ForgettingFactorAdaptation<double>(lambda));
  update.reset(theta0, P0);
  for (int k = 0; k < r.phi.rows(); ++k) {
    update.update(r.phi.row(k).transpose(), r.y(k));
  }
  EXPECT_LT(test::relative_error(update.theta(),
                                 weighted_batch(r, lambda, theta0, P0)),
            1e-9);
}

TEST(ParameterUpdate, KalmanWithZeroQnEqualsRlsWithUnitForgetting) {
  const int np = 3;
  const Regression r = make_regression(150, np, 3);
  ParameterUpdate<double> rls(np, ForgettingFactorAdaptation<double>(1.0));
  ParameterUpdate<double> kf(
      np, KalmanAdaptation<double>(Eigen::MatrixXd::Zero(np, np)));
  const Eigen::MatrixXd P0 = 1e4 * Eigen::MatrixXd::Identity(np, np);
  rls.reset(Eigen::VectorXd::Zero(np), P0);
  kf.reset(Eigen::VectorXd::Zero(np), P0);
  for (int k = 0; k < r.phi.rows(); ++k) {
    rls.update(r.phi.row(k).transpose(), r.y(k));
    kf.update(r.phi.row(k).transpose(), r.y(k));
    ASSERT_TRUE(test::MatrixNear(kf.theta(), rls.theta(), 1e-12));
    ASSERT_TRUE(test::MatrixNear(kf.P(), rls.P(), 1e-12));
  }
}

// The normalised Kalman filter (1.45) equals the standard one (1.43) with
// sigma_e^2 = s and Qw = s Qn, whose covariance is s P (eq. 1.44). The
// standard filter is written out here with an explicit inverse.
TEST(ParameterUpdate, NormalisedKalmanMatchesStandardKalmanFilter) {
  const int np = 3;
  const Regression r = make_regression(200, np, 4);
  const double s = 0.37;
  Eigen::MatrixXd qn(np, np);
  qn << 1e-3, 1e-4, 0, 1e-4, 2e-3, 0, 0, 0, 5e-4;
  ParameterUpdate<double> kf(np, KalmanAdaptation<double>(qn));
  const Eigen::MatrixXd P0 = 10 * Eigen::MatrixXd::Identity(np, np);
  kf.reset(Eigen::VectorXd::Zero(np), P0);
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(np);
  Eigen::MatrixXd P = s * P0;
  for (int k = 0; k < r.phi.rows(); ++k) {
    const Eigen::VectorXd phi = r.phi.row(k).transpose();
    const Eigen::MatrixXd Pp = P + s * qn;
    const Eigen::MatrixXd S =
        phi.transpose() * Pp * phi + s * Eigen::MatrixXd::Identity(1, 1);
    const Eigen::VectorXd L = Pp * phi * S.inverse();
    theta += L * (r.y(k) - phi.dot(theta));
    P = Pp - L * phi.transpose() * Pp;
    kf.update(phi, r.y(k));
  }
  EXPECT_TRUE(test::MatrixNear(kf.theta(), theta, 1e-10));
  EXPECT_TRUE(test::MatrixNear(kf.P() * s, P, 1e-10));
}

TEST(ParameterUpdate, InstrumentsEqualToRegressorsGiveLeastSquares) {
  const int np = 3;
  const Regression r = make_regression(100, np, 5);
  ParameterUpdate<double> ls(np, ForgettingFactorAdaptation<double>(0.99));
  ParameterUpdate<double> iv(np, ForgettingFactorAdaptation<double>(0.99));
  const Eigen::MatrixXd P0 = 1e4 * Eigen::MatrixXd::Identity(np, np);
  ls.reset(Eigen::VectorXd::Zero(np), P0);
  iv.reset(Eigen::VectorXd::Zero(np), P0);
  for (int k = 0; k < r.phi.rows(); ++k) {
    const Eigen::VectorXd phi = r.phi.row(k).transpose();
    ls.update(phi, r.y(k));
    iv.update(phi, phi, r.y(k));
  }
  EXPECT_TRUE(test::MatrixNear(iv.theta(), ls.theta(), 1e-10));
  EXPECT_TRUE(test::MatrixNear(iv.P(), ls.P(), 1e-10));
}

// Recursive IV with unit forgetting solves
//   (P0^-1 + sum zeta phi^T) theta = P0^-1 theta0 + sum zeta y.
TEST(ParameterUpdate, RecursiveIvEqualsBatchIv) {
  const int np = 3;
  const Regression r = make_regression(250, np, 6);
  const Eigen::MatrixXd P0 = 50 * Eigen::MatrixXd::Identity(np, np);
  const Eigen::VectorXd theta0(Eigen::Vector3d(0.1, -0.2, 0.3));
  ParameterUpdate<double> iv(np, ForgettingFactorAdaptation<double>(1.0));
  iv.reset(theta0, P0);
  Eigen::MatrixXd lhs = P0.inverse();
  Eigen::VectorXd rhs = P0.inverse() * theta0;
  for (int k = 0; k < r.phi.rows(); ++k) {
    const Eigen::VectorXd phi = r.phi.row(k).transpose();
    const Eigen::VectorXd zeta = r.zeta.row(k).transpose();
    iv.update(phi, zeta, r.y(k));
    lhs += zeta * phi.transpose();
    rhs += zeta * r.y(k);
  }
  const Eigen::VectorXd batch = lhs.fullPivLu().solve(rhs);
  EXPECT_LT(test::relative_error(iv.theta(), batch), 1e-9);
}

// With forgetting the asymmetric rounding of P is amplified by 1/lambda at
// every step; a non-symmetric update let P turn indefinite within 1e5
// samples at lambda = 0.999 (found by the benchmark). P must stay exactly
// symmetric and positive definite, and theta near the truth.
TEST(ParameterUpdate, ForgettingFactorKeepsPSymmetricOverLongRuns) {
  const int np = 3, n = 100000;
  std::mt19937 rng(12);
  std::normal_distribution<double> normal;
  const Eigen::Vector3d truth(1.0, -2.0, 0.5);
  for (double lambda : {0.99, 0.999}) {
    ParameterUpdate<double> update(np,
                                   ForgettingFactorAdaptation<double>(lambda));
    update.reset(Eigen::VectorXd::Zero(np),
                 1e4 * Eigen::MatrixXd::Identity(np, np));
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d phi(normal(rng), normal(rng), 10 * normal(rng));
      update.update(phi, phi.dot(truth) + 0.1 * normal(rng));
    }
    const Eigen::MatrixXd& P = update.P();
    EXPECT_EQ((P - P.transpose()).cwiseAbs().maxCoeff(), 0.0) << lambda;
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P)
                  .eigenvalues()
                  .minCoeff(),
              0.0)
        << lambda;
    EXPECT_LT((update.theta() - truth).norm(), 0.05) << lambda;
  }
}

TEST(Kappa2, EigenvalueRatioForSymmetricSingularValuesOtherwise) {
  Eigen::MatrixXd sym(2, 2);
  sym << 4, 0, 0, 0.5;
  EXPECT_NEAR(kappa_2<double>(sym), 8.0, 1e-12);
  sym(1, 1) = -0.5;  // indefinite: reported as infinite
  EXPECT_TRUE(std::isinf(kappa_2<double>(sym)));
  Eigen::MatrixXd general(2, 2);
  general << 1, 2, 0, 1;  // singular values 1 +- sqrt(2)
  EXPECT_NEAR(kappa_2<double>(general),
              (1 + std::sqrt(2.0)) / (std::sqrt(2.0) - 1), 1e-12);
}

TEST(Validation, ForgettingFactorRange) {
  EXPECT_TRUE(validate_forgetting_factor(1.0).ok());
  EXPECT_TRUE(validate_forgetting_factor(0.5).ok());
  EXPECT_FALSE(validate_forgetting_factor(0.0).ok());
  EXPECT_FALSE(validate_forgetting_factor(1.01).ok());
  EXPECT_FALSE(validate_forgetting_factor(std::nan("")).ok());
}

TEST(Validation, CovarianceShapeSymmetryAndDefiniteness) {
  Eigen::MatrixXd good = Eigen::MatrixXd::Identity(3, 3);
  EXPECT_TRUE(validate_covariance<double>(good, 3, "Qn", false).ok());
  EXPECT_EQ(validate_covariance<double>(good, 2, "Qn", false).code(),
            ErrorCode::kDimensionMismatch);
  Eigen::MatrixXd asym = good;
  asym(0, 1) = 0.5;
  EXPECT_EQ(validate_covariance<double>(asym, 3, "Qn", false).code(),
            ErrorCode::kBadInput);
  Eigen::MatrixXd indefinite = good;
  indefinite(2, 2) = -1;
  EXPECT_EQ(validate_covariance<double>(indefinite, 3, "Qn", false).code(),
            ErrorCode::kBadInput);
  EXPECT_TRUE(
      validate_covariance<double>(Eigen::MatrixXd::Zero(3, 3), 3, "Qn", false)
          .ok());
  EXPECT_FALSE(
      validate_covariance<double>(Eigen::MatrixXd::Zero(3, 3), 3, "P0", true)
          .ok());
  Eigen::MatrixXd inf = good;
  inf(1, 1) = INFINITY;
  EXPECT_FALSE(validate_covariance<double>(inf, 3, "Qn", false).ok());
}

}  // namespace
}  // namespace ctid
