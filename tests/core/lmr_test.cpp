// Tests of core/include/ctid/adaptation/lmr.hpp: LMR-RLSSVF, eq. (3.82), against the
// covariance-form least squares it generalises, its bounded information
// under poor excitation (sec. 3.6.3), and no allocation per step.
#include "ctid/adaptation/lmr.hpp"

#include <gtest/gtest.h>

#include <random>

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

}  // namespace
}  // namespace ctid
