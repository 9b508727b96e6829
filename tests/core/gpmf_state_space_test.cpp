// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of the GPMF state-space estimators (gpmf_state_space.hpp): the
// canonical realisation matches the input-output equations it comes from,
// a canonical system is recovered from noise-free data simulated through
// the matrix exponential, IV and bias compensation remove the bias of LS
// under output noise, and bad input is reported.
#include "ctid/offline/gpmf_state_space.hpp"

#include <complex>
#include <iostream>
#include <random>

#include "test_util.hpp"

namespace {

using Complex = std::complex<double>;
using CMatrix = Eigen::MatrixXcd;

// The order-3, 2-output, 2-input system in the canonical form of the
// indices [2 1]: x = [y1, y1' - B(0,:) u, y2].
struct CanonicalSystem {
  Eigen::MatrixXd A{{0, 1, 0}, {-4, -4, 2}, {-2, -1, 0}};
  Eigen::MatrixXd B{{2, 1}, {-3, -1}, {0, 1}};
  Eigen::MatrixXd C{{1, 0, 0}, {0, 0, 1}};
};

CMatrix frequency_response(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                           const Eigen::MatrixXd& C, double w) {
  const Eigen::Index n = A.rows();
  CMatrix resolvent =
      Complex(0, w) * CMatrix::Identity(n, n) - A.cast<Complex>();
  return C.cast<Complex>() * resolvent.lu().solve(B.cast<Complex>());
}

// Exact ZOH response from rest (matrix exponential of the augmented
// matrix), y N-by-p column-major.
Eigen::MatrixXd simulate_zoh(const CanonicalSystem& s, const Eigen::MatrixXd& u,
                             double h) {
  const Eigen::Index n = s.A.rows(), m = s.B.cols();
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n + m, n + m);
  F.topLeftCorner(n, n) = s.A * h;
  F.topRightCorner(n, m) = s.B * h;
  const Eigen::MatrixXd E = F.exp();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd y(u.rows(), s.C.rows());
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    y.row(k) = (s.C * x).transpose();
    x = E.topLeftCorner(n, n) * x +
        E.topRightCorner(n, m) * u.row(k).transpose();
  }
  return y;
}

Eigen::MatrixXd binary_inputs(int n) {
  const std::vector<double> u1 = ctid::test::binary_input(n, 50, 3);
  const std::vector<double> u2 = ctid::test::binary_input(n, 70, 5);
  Eigen::MatrixXd u(n, 2);
  for (int k = 0; k < n; ++k) {
    u(k, 0) = u1[k];
    u(k, 1) = u2[k];
  }
  return u;
}

ctid::MultiRecordView<double> view(const Eigen::MatrixXd& y,
                                   const Eigen::MatrixXd& u, double h) {
  ctid::MultiRecordView<double> record;
  record.y = y.data();
  record.u = u.data();
  record.num_samples = y.rows();
  record.num_outputs = y.cols();
  record.num_inputs = u.cols();
  record.ts = h;
  return record;
}

ctid::GpmfSettings<double> settings_21() {
  ctid::GpmfSettings<double> settings;
  settings.observability_indices = {2, 1};
  settings.lambda = {3.0, 3.0};
  return settings;
}

// C (sI - A)^-1 B of the canonical realisation equals P(s)^-1 Q(s) of the
// equations p^(n_i) y_i + sum alpha p^k y_j = sum beta p^k u_l read from
// the same theta (any theta: the identity is algebraic).
TEST(GpmfStateSpace, RealisationMatchesInputOutputEquations) {
  const std::vector<int> n = {2, 3, 1};
  const int p = 3, m = 2;
  Eigen::Index count = 0;
  for (int i = 0; i < p; ++i) {
    count += ctid::gpmf_detail::num_alpha(n, i) + n[i] * m;
  }
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd theta(count);
  for (Eigen::Index k = 0; k < count; ++k) theta(k) = uniform(rng);
  ctid::StateSpaceEstimate<double> model;
  ASSERT_TRUE(ctid::gpmf_detail::canonical_model(n, m, theta, &model).ok());
  for (double w : {0.3, 1.7}) {
    const Complex s(0, w);
    CMatrix P = CMatrix::Zero(p, p), Q = CMatrix::Zero(p, m);
    Eigen::Index offset = 0;
    for (int i = 0; i < p; ++i) {
      P(i, i) = std::pow(s, n[i]);
      for (int j = 0; j < p; ++j) {
        for (int k = 0; k < ctid::gpmf_detail::coupling_degree(n, i, j); ++k) {
          P(i, j) += theta(offset++) * std::pow(s, k);
        }
      }
      for (int l = 0; l < m; ++l) {
        for (int k = 0; k < n[i]; ++k) {
          Q(i, l) += theta(offset++) * std::pow(s, k);
        }
      }
    }
    const CMatrix expected = P.lu().solve(Q);
    const CMatrix H = frequency_response(model.A, model.B, model.C, w);
    EXPECT_LT((H - expected).norm() / expected.norm(), 1e-12) << "w = " << w;
  }
}

// Noise-free data of a canonical system: LS and IV return its A and B up
// to the trapezoidal filtering of y, O((lambda h)^2) ~ 1e-3 relative.
TEST(GpmfStateSpace, RecoversCanonicalSystemFromNoiseFreeData) {
  const CanonicalSystem system;
  const double h = 0.01;
  const Eigen::MatrixXd u = binary_inputs(6000);
  const Eigen::MatrixXd y = simulate_zoh(system, u, h);
  const auto record = view(y, u, h);
  for (bool iv : {false, true}) {
    ctid::StateSpaceEstimate<double> estimate;
    const ctid::Status status =
        iv ? ctid::ss_iv_gpmf(record, settings_21(), &estimate)
           : ctid::ss_ls_gpmf(record, settings_21(), &estimate);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_LT((estimate.A - system.A).norm() / system.A.norm(), 1e-3)
        << (iv ? "IV" : "LS") << "\n"
        << estimate.A;
    EXPECT_LT((estimate.B - system.B).norm() / system.B.norm(), 1e-3)
        << (iv ? "IV" : "LS") << "\n"
        << estimate.B;
    EXPECT_EQ(estimate.C, system.C);
    EXPECT_TRUE(estimate.D.isZero());
  }
}

// White output noise: LS is biased; IV is several times closer.
TEST(GpmfStateSpace, InstrumentsRemoveTheNoiseBias) {
  const CanonicalSystem system;
  const double h = 0.01;
  const Eigen::MatrixXd u = binary_inputs(20000);
  Eigen::MatrixXd y = simulate_zoh(system, u, h);
  std::mt19937 rng(21);
  std::normal_distribution<double> normal(0, 1);
  for (Eigen::Index j = 0; j < y.cols(); ++j) {
    const double sigma = 0.3 * std::sqrt(y.col(j).squaredNorm() / y.rows());
    for (Eigen::Index k = 0; k < y.rows(); ++k) y(k, j) += sigma * normal(rng);
  }
  const auto record = view(y, u, h);
  ctid::StateSpaceEstimate<double> ls, iv;
  ASSERT_TRUE(ctid::ss_ls_gpmf(record, settings_21(), &ls).ok());
  ASSERT_TRUE(ctid::ss_iv_gpmf(record, settings_21(), &iv).ok());
  Eigen::MatrixXd truth(3, 5), ls_ab(3, 5), iv_ab(3, 5);
  truth << system.A, system.B;
  ls_ab << ls.A, ls.B;
  iv_ab << iv.A, iv.B;
  const double error_ls = (ls_ab - truth).norm();
  const double error_iv = (iv_ab - truth).norm();
  EXPECT_LT(error_iv, error_ls / 3) << "LS " << error_ls << " IV " << error_iv;
}

TEST(GpmfStateSpace, ReportsBadInput) {
  const CanonicalSystem system;
  const Eigen::MatrixXd u = binary_inputs(500);
  const Eigen::MatrixXd y = simulate_zoh(system, u, 0.01);
  const auto record = view(y, u, 0.01);
  ctid::StateSpaceEstimate<double> estimate;
  auto settings = settings_21();
  settings.observability_indices = {2, 1, 1};
  EXPECT_EQ(ctid::ss_ls_gpmf(record, settings, &estimate).code(),
            ctid::ErrorCode::kDimensionMismatch);
  settings = settings_21();
  settings.lambda = {3.0};
  EXPECT_EQ(ctid::ss_ls_gpmf(record, settings, &estimate).code(),
            ctid::ErrorCode::kDimensionMismatch);
  settings = settings_21();
  settings.lambda = {3.0, -1.0};
  EXPECT_EQ(ctid::ss_ls_gpmf(record, settings, &estimate).code(),
            ctid::ErrorCode::kBadInput);
  settings = settings_21();
  settings.observability_indices = {0, 1};
  EXPECT_EQ(ctid::ss_ls_gpmf(record, settings, &estimate).code(),
            ctid::ErrorCode::kBadInput);
  settings = settings_21();
  settings.first_sample = 495;
  EXPECT_EQ(ctid::ss_ls_gpmf(record, settings, &estimate).code(),
            ctid::ErrorCode::kBadInput);
  Eigen::MatrixXd bad = y;
  bad(7, 1) = std::nan("");
  EXPECT_EQ(
      ctid::ss_iv_gpmf(view(bad, u, 0.01), settings_21(), &estimate).code(),
      ctid::ErrorCode::kBadInput);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(500, 2);
  EXPECT_EQ(
      ctid::ss_ls_gpmf(view(y, zero, 0.01), settings_21(), &estimate).code(),
      ctid::ErrorCode::kNumericalFailure);
}

// One artificial root per output, away from the poles -2, -1 +- i (a root
// at a pole makes the augmented equation non-unique).
std::vector<std::vector<double>> demo_roots() {
  return {{-1.0}, {-1.0}};
}

// Noise-free data: the bias-compensated estimate finds almost no noise
// (variance estimates below 1e-3 of the output power, what the filtering
// error leaves in the constraints) and returns the system, as LS does, up
// to the same filtering error.
TEST(GpmfStateSpace, BiasCompensationEqualsLeastSquaresWithoutNoise) {
  const CanonicalSystem system;
  const double h = 0.01;
  const Eigen::MatrixXd u = binary_inputs(6000);
  const Eigen::MatrixXd y = simulate_zoh(system, u, h);
  const auto record = view(y, u, h);
  ctid::StateSpaceEstimate<double> ls, bc;
  Eigen::VectorXd variance;
  ASSERT_TRUE(ctid::ss_ls_gpmf(record, settings_21(), &ls).ok());
  const ctid::Status status =
      ctid::ss_bc_gpmf(record, settings_21(), demo_roots(), &bc, &variance);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(variance.size(), 2);
  for (Eigen::Index j = 0; j < 2; ++j) {
    EXPECT_LT(variance(j), 1e-3 * y.col(j).squaredNorm() / y.rows());
  }
  EXPECT_LT((bc.A - system.A).norm() / system.A.norm(), 1e-3) << bc.A;
  EXPECT_LT((bc.B - system.B).norm() / system.B.norm(), 1e-3) << bc.B;
  EXPECT_LT((bc.A - ls.A).norm() / system.A.norm(), 2e-3);
  EXPECT_LT((bc.B - ls.B).norm() / system.B.norm(), 2e-3);
  EXPECT_EQ(bc.C, system.C);
  EXPECT_TRUE(bc.D.isZero());
}

// Monte Carlo under white output noise (fixed seed): the mean LS estimate
// of A is several standard errors away from the truth, the mean
// bias-compensated estimate of every entry of A and B is within 3
// standard errors of it.
TEST(GpmfStateSpace, BiasCompensationRemovesTheNoiseBias) {
  const CanonicalSystem system;
  const double h = 0.01;
  const int runs = 40;
  const Eigen::MatrixXd u = binary_inputs(20000);
  const Eigen::MatrixXd y0 = simulate_zoh(system, u, h);
  Eigen::Vector2d sigma;
  for (Eigen::Index j = 0; j < 2; ++j) {
    sigma(j) = 0.3 * std::sqrt(y0.col(j).squaredNorm() / y0.rows());
  }
  Eigen::MatrixXd truth(3, 5);
  truth << system.A, system.B;
  Eigen::MatrixXd sum_ls = Eigen::MatrixXd::Zero(3, 5), sum_bc = sum_ls;
  Eigen::MatrixXd sq_ls = sum_ls, sq_bc = sum_ls;
  Eigen::Vector2d sum_var = Eigen::Vector2d::Zero();
  std::mt19937 rng(31);
  std::normal_distribution<double> normal(0, 1);
  for (int run = 0; run < runs; ++run) {
    Eigen::MatrixXd y = y0;
    for (Eigen::Index j = 0; j < 2; ++j) {
      for (Eigen::Index k = 0; k < y.rows(); ++k) {
        y(k, j) += sigma(j) * normal(rng);
      }
    }
    const auto record = view(y, u, h);
    ctid::StateSpaceEstimate<double> ls, bc;
    Eigen::VectorXd variance;
    ASSERT_TRUE(ctid::ss_ls_gpmf(record, settings_21(), &ls).ok());
    const ctid::Status status =
        ctid::ss_bc_gpmf(record, settings_21(), demo_roots(), &bc, &variance);
    ASSERT_TRUE(status.ok()) << status.message();
    Eigen::MatrixXd ls_ab(3, 5), bc_ab(3, 5);
    ls_ab << ls.A, ls.B;
    bc_ab << bc.A, bc.B;
    sum_ls += ls_ab;
    sum_bc += bc_ab;
    sq_ls += ls_ab.cwiseAbs2();
    sq_bc += bc_ab.cwiseAbs2();
    sum_var += variance;
  }
  const auto standard_error = [&](const Eigen::MatrixXd& sum,
                                  const Eigen::MatrixXd& sq) {
    const Eigen::MatrixXd mean = sum / runs;
    const Eigen::MatrixXd var =
        (sq - runs * mean.cwiseAbs2()) / static_cast<double>(runs - 1);
    return Eigen::MatrixXd(var.cwiseMax(0).cwiseSqrt() / std::sqrt(runs));
  };
  const Eigen::MatrixXd se_ls = standard_error(sum_ls, sq_ls);
  const Eigen::MatrixXd se_bc = standard_error(sum_bc, sq_bc);
  // Distance of the mean from the truth in standard errors; the entries
  // fixed by the canonical form (0 and 1 in A) have no spread and are 0.
  const auto z_score = [&](const Eigen::MatrixXd& sum,
                           const Eigen::MatrixXd& se) {
    Eigen::MatrixXd z = Eigen::MatrixXd::Zero(3, 5);
    for (Eigen::Index r = 0; r < 3; ++r) {
      for (Eigen::Index c = 0; c < 5; ++c) {
        if (se(r, c) > 0) {
          z(r, c) = std::abs(sum(r, c) / runs - truth(r, c)) / se(r, c);
        }
      }
    }
    return z;
  };
  const Eigen::MatrixXd z_ls = z_score(sum_ls, se_ls);
  const Eigen::MatrixXd z_bc = z_score(sum_bc, se_bc);
  std::cout << "mean LS [A B]\n" << sum_ls / runs << "\nSE LS\n" << se_ls
            << "\nmean BC [A B]\n" << sum_bc / runs << "\nSE BC\n" << se_bc
            << "\nnoise variance " << (sum_var / runs).transpose()
            << " true " << sigma.cwiseAbs2().transpose() << "\n";
  // The free row of A (row 2) and the coupling row (row 3).
  EXPECT_GT(z_ls.topLeftCorner(3, 3).maxCoeff(), 10) << z_ls;
  EXPECT_LT(z_bc.maxCoeff(), 3) << z_bc;
  // The noise of y1 enters both output equations and is recovered; that
  // of y2 is weakly determined by these constraints (about 60 % of the
  // true variance here) and is not checked.
  EXPECT_NEAR(sum_var(0) / runs, sigma(0) * sigma(0),
              0.1 * sigma(0) * sigma(0));
}

TEST(GpmfStateSpace, BiasCompensationReportsBadInput) {
  const CanonicalSystem system;
  const Eigen::MatrixXd u = binary_inputs(500);
  const Eigen::MatrixXd y = simulate_zoh(system, u, 0.01);
  const auto record = view(y, u, 0.01);
  ctid::StateSpaceEstimate<double> estimate;
  EXPECT_EQ(ctid::ss_bc_gpmf(record, settings_21(), {{-1.0}}, &estimate)
                .code(),
            ctid::ErrorCode::kDimensionMismatch);
  EXPECT_EQ(ctid::ss_bc_gpmf(record, settings_21(), {{-1.0}, {}}, &estimate)
                .code(),
            ctid::ErrorCode::kBadInput);
  EXPECT_EQ(
      ctid::ss_bc_gpmf(record, settings_21(), {{-1.0}, {0.5}}, &estimate)
          .code(),
      ctid::ErrorCode::kBadInput);
  std::vector<double> instants(500);
  for (int k = 0; k < 500; ++k) instants[k] = 0.01 * k;
  auto irregular = record;
  irregular.instants = instants.data();
  EXPECT_EQ(ctid::ss_bc_gpmf(irregular, settings_21(), demo_roots(),
                             &estimate)
                .code(),
            ctid::ErrorCode::kBadInput);
}

// The subspace method on the same noise-free record: the frequency
// response (state basis free) is the true one up to the filtering error,
// and the order is found at the gap of the singular values.
TEST(GpmfStateSpace, SubspaceRecoversFrequencyResponse) {
  const CanonicalSystem system;
  const double h = 0.01;
  const Eigen::MatrixXd u = binary_inputs(6000);
  const Eigen::MatrixXd y = simulate_zoh(system, u, h);
  ctid::SubspaceGpmfSettings settings;
  settings.block_rows = 3;
  settings.filter_order = 3;
  settings.lambda = 3;
  ctid::SubspaceGpmfEstimate<double> estimate;
  const ctid::Status status =
      ctid::sid_gpmf(view(y, u, h), settings, &estimate);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(estimate.model.A.rows(), 3);
  for (double w : {0.1, 1.0, 10.0}) {
    const CMatrix H0 = frequency_response(system.A, system.B, system.C, w);
    const CMatrix H = frequency_response(estimate.model.A, estimate.model.B,
                                         estimate.model.C, w) +
                      estimate.model.D.cast<Complex>();
    EXPECT_LT((H - H0).norm() / H0.norm(), 1e-3) << "w = " << w;
  }
  settings.order = 5;  // > (i - 1) p = 4
  EXPECT_EQ(ctid::sid_gpmf(view(y, u, h), settings, &estimate).code(),
            ctid::ErrorCode::kBadInput);
  settings.order = 3;
  settings.block_rows = 1;
  EXPECT_EQ(ctid::sid_gpmf(view(y, u, h), settings, &estimate).code(),
            ctid::ErrorCode::kBadInput);
}

}  // namespace
