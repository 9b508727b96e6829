// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of recursive_arx.hpp: the indirect route (DT ARX + ZOH conversion).
#include "ctid/recursive/recursive_arx.hpp"

#include <gtest/gtest.h>

#include "ctid/filters/discretization.hpp"
#include "test_util.hpp"

namespace {

using ctid::Matrix;
using ctid::Vector;
using ctid::test::MatrixNear;

// ZOH sampling of B(p)/A(p) by the matrix exponential (discretization.hpp,
// an independent path from the logarithm): DT [alpha], [beta_z] in z.
void sample_zoh(const Vector<double>& a, const Vector<double>& b, double ts,
                Vector<double>* alpha, Vector<double>* beta_z) {
  const Eigen::Index n = a.size();
  const Matrix<double> F = ctid::companion_matrix<double>(a);
  Matrix<double> G = Matrix<double>::Zero(n, 1);
  G(n - 1, 0) = 1;
  Matrix<double> Phi, Gamma;
  ctid::zoh_discretize<double>(F, G, ts, Phi, Gamma);
  Vector<double> C(n);  // B(p) w with w = [w .. w^(n-1)]
  for (Eigen::Index j = 0; j < n; ++j) C(j) = b(n - 1 - j);
  *alpha = ctid::characteristic_polynomial<double>(Phi);
  const Matrix<double> closed = Phi - Gamma * C.transpose();
  *beta_z = ctid::characteristic_polynomial<double>(closed) - *alpha;
}

TEST(ZohToContinuous, InvertsTheMatrixExponentialMap) {
  // Second order underdamped (thesis eq. 1.61 at t = 0: wn = 2.6, zeta 0.6),
  // and a third-order system with a zero.
  const std::vector<std::pair<Vector<double>, Vector<double>>> systems = {
      {(Vector<double>(2) << 2 * 0.6 * 2.6, 2.6 * 2.6).finished(),
       (Vector<double>(2) << 0, 2.6 * 2.6).finished()},
      {(Vector<double>(3) << 3.5, 7.0, 4.0).finished(),
       (Vector<double>(3) << 0.5, -1.0, 4.0).finished()}};
  for (const auto& [a, b] : systems) {
    for (double ts : {0.01, 0.1, 0.5}) {
      Vector<double> alpha, beta_z, a_back, b_back;
      sample_zoh(a, b, ts, &alpha, &beta_z);
      const ctid::Status s =
          ctid::zoh_to_continuous<double>(alpha, beta_z, ts, &a_back, &b_back);
      ASSERT_TRUE(s.ok()) << s.message();
      EXPECT_TRUE(MatrixNear(a_back, a, 1e-9)) << "Ts " << ts;
      EXPECT_TRUE(MatrixNear(b_back, b, 1e-9)) << "Ts " << ts;
    }
  }
}

TEST(ZohToContinuous, NegativeRealPoleHasNoCtEquivalent) {
  Vector<double> alpha(1), beta(1), a, b;
  alpha << 0.5;  // z + 0.5: pole at -0.5
  beta << 1;
  const ctid::Status s =
      ctid::zoh_to_continuous<double>(alpha, beta, 0.1, &a, &b);
  EXPECT_EQ(s.code(), ctid::ErrorCode::kNumericalFailure);
}

// Regressors of the ARX model (1.6) built directly, for the batch check.
Matrix<double> arx_regressors(const std::vector<double>& y,
                              const std::vector<double>& u, int na, int nb,
                              int nk) {
  const int n = static_cast<int>(y.size());
  Matrix<double> Phi = Matrix<double>::Zero(n, na + nb);
  for (int k = 0; k < n; ++k) {
    for (int i = 1; i <= na; ++i) Phi(k, i - 1) = k - i >= 0 ? -y[k - i] : 0;
    for (int j = 0; j < nb; ++j) {
      Phi(k, na + j) = k - nk - j >= 0 ? u[k - nk - j] : 0;
    }
  }
  return Phi;
}

TEST(RecursiveArx, RlsEqualsTheBatchLeastSquaresSolution) {
  const int n = 400;
  const std::vector<double> u = ctid::test::binary_input(n, 3, 11);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.1);
  std::vector<double> y(n, 0.0);
  for (int k = 0; k < n; ++k) {
    const double y1 = k >= 1 ? y[k - 1] : 0, y2 = k >= 2 ? y[k - 2] : 0;
    const double u1 = k >= 1 ? u[k - 1] : 0, u2 = k >= 2 ? u[k - 2] : 0;
    y[k] = 1.5 * y1 - 0.7 * y2 + 0.3 * u1 + 0.2 * u2 + noise(rng);
  }
  ctid::RecursiveArxConfig<double> config;
  config.na = 2;
  config.nb = 2;
  config.nk = 1;
  config.ts = 0.1;
  config.P0 = 1e8 * Matrix<double>::Identity(4, 4);
  Matrix<double> thm(n, 4);
  ctid::RecursiveArxOutputs<double> out;
  out.theta = thm.data();
  long failures = 0;
  const ctid::Status s = ctid::run_recursive_arx<double>(
      config, y.data(), u.data(), n, out, &failures);
  ASSERT_TRUE(s.ok()) << s.message();
  // RLS from theta0 = 0, P0 = c I minimises sum e^2 + |theta|^2 / c: the
  // regularised normal equations, eq. (1.12) plus I/c.
  const Matrix<double> Phi = arx_regressors(y, u, 2, 2, 1);
  const Vector<double> Y = Eigen::Map<const Vector<double>>(y.data(), n);
  const Matrix<double> normal =
      Phi.transpose() * Phi + 1e-8 * Matrix<double>::Identity(4, 4);
  const Vector<double> batch = normal.ldlt().solve(Phi.transpose() * Y);
  EXPECT_TRUE(MatrixNear(Vector<double>(thm.row(n - 1).transpose()), batch,
                         1e-8));
}

TEST(RecursiveArx, NoiseFreeZohRecordGivesTheCtModel) {
  // The CT system of eq. (1.61) frozen at t = 0, sampled with ZOH input.
  const double wn = 2.6, zeta = 0.6, ts = 0.1;
  Vector<double> a(2), b(2);
  a << 2 * zeta * wn, wn * wn;
  b << 0, wn * wn;
  Vector<double> alpha, beta_z;
  sample_zoh(a, b, ts, &alpha, &beta_z);
  const int n = 3000;
  const std::vector<double> u = ctid::test::binary_input(n, 10, 3);
  std::vector<double> y(n, 0.0);
  for (int k = 0; k < n; ++k) {
    double v = 0;
    for (int i = 1; i <= 2; ++i) {
      if (k - i >= 0) v += -alpha(i - 1) * y[k - i] + beta_z(i - 1) * u[k - i];
    }
    y[k] = v;
  }
  ctid::RecursiveArxConfig<double> config;
  config.na = 2;
  config.nb = 2;
  config.nk = 1;
  config.ts = ts;
  // RLS from P0 = c I carries the prior |rho|^2 / c; with the default
  // c = 1e4 it biases the ill-conditioned ARX regression by ~1e-4, so the
  // exactness check uses a negligible prior.
  config.P0 = 1e12 * Matrix<double>::Identity(4, 4);
  Matrix<double> thm_ct(n, 4);
  Matrix<double> failed(n, 1);
  ctid::RecursiveArxOutputs<double> out;
  out.theta_ct = thm_ct.data();
  out.conversion_failed = failed.data();
  long failures = -1;
  const ctid::Status s = ctid::run_recursive_arx<double>(
      config, y.data(), u.data(), n, out, &failures);
  ASSERT_TRUE(s.ok()) << s.message();
  Vector<double> expected(4);
  expected << a, b;
  EXPECT_TRUE(MatrixNear(Vector<double>(thm_ct.row(n - 1).transpose()),
                         expected, 1e-6));
  EXPECT_EQ(failed(n - 1, 0), 0);
}

TEST(RecursiveArx, RejectsOrdersWithoutAZohImage) {
  ctid::RecursiveArxConfig<double> config;
  config.na = 2;
  config.nb = 2;
  config.nk = 0;  // beta_0 u(t_k): not strictly proper
  config.ts = 0.1;
  EXPECT_EQ(ctid::validate(config).code(), ctid::ErrorCode::kBadInput);
  config.to_continuous = false;
  EXPECT_TRUE(ctid::validate(config).ok());
  config.ts = 0;
  EXPECT_EQ(ctid::validate(config).code(), ctid::ErrorCode::kBadInput);
}

}  // namespace
