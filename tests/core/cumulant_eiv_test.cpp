// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/offline/cumulant_eiv.hpp: recovery of a
// noise-free system, consistency of TOCLS and TOCILS on records with noise
// on the input and the output where LSSVF and IVSVF are biased, and the
// refusal of inputs the method cannot use.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ctid/offline/cumulant_eiv.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

// (p - 1) / (p^2 + 2 p + 1): theta = [a1 a2 b0 b1].
const ModelOrders kOrders = siso_orders(2, 2, 0);
Eigen::VectorXd true_theta() { return Eigen::Vector4d(2.0, 1.0, 1.0, -1.0); }

RecordView<double> view(const std::vector<double>& y,
                        const std::vector<double>& u, double ts) {
  RecordView<double> record;
  record.y = y.data();
  record.u = u.data();
  record.num_samples = static_cast<Eigen::Index>(y.size());
  record.num_inputs = 1;
  record.ts = ts;
  return record;
}

// A skewed input: chi-square (2 degrees of freedom) white noise, coloured
// by 1 - 0.2 q^-1 + 0.3 q^-2 and standardised.
std::vector<double> skewed_input(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<double> w(n), u(n);
  for (auto& v : w) {
    const double a = normal(rng), b = normal(rng);
    v = a * a + b * b;
  }
  for (int k = 0; k < n; ++k) {
    u[k] = w[k] - (k >= 1 ? 0.2 * w[k - 1] : 0.0) +
           (k >= 2 ? 0.3 * w[k - 2] : 0.0);
  }
  double mean = 0, var = 0;
  for (double v : u) mean += v;
  mean /= n;
  for (double v : u) var += (v - mean) * (v - mean);
  const double sd = std::sqrt(var / n);
  for (auto& v : u) v = (v - mean) / sd;
  return u;
}

std::vector<double> plant_output(const std::vector<double>& u, double ts) {
  return test::simulate_zoh(Eigen::Vector2d(1.0, -1.0),
                            Eigen::Vector3d(1.0, 2.0, 1.0), u, ts);
}

SvfSettings<double> svf_with(double lambda) {
  SvfSettings<double> svf;
  svf.lambda_svf = lambda;
  svf.u_intersample = InterSample::kZoh;
  return svf;
}

// Noise-free, the TOCLS equations hold up to the SVF's discretisation
// error of the output channel (O(Ts^2)), so TOCLS is within that of the
// true parameters and its error shrinks with Ts. TOCILS's prefilter is
// the model's own denominator, for which the filtered equation holds
// exactly (as for SRIVC): the true parameters are its fixed point, up to
// rounding.
TEST(CumulantEiv, NoiseFreeRecordIsRecovered) {
  CumulantEivSettings<double> settings;
  settings.lags = 50;
  settings.tolerance = 1e-10;
  settings.max_iterations = 50;
  double error_ls[2], error_ils[2];
  const double steps[2] = {0.02, 0.01};
  for (int i = 0; i < 2; ++i) {
    const double ts = steps[i];
    const auto u = skewed_input(20000, 3);
    const auto y = plant_output(u, ts);
    CumulantEivEstimate<double> ls, ils;
    Status status = tocls(kOrders, svf_with(3), view(y, u, ts), settings, &ls);
    ASSERT_TRUE(status.ok()) << status.message();
    status = tocils(kOrders, svf_with(3), view(y, u, ts), settings, &ils);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_TRUE(ils.converged);
    error_ls[i] = test::relative_error(ls.theta, true_theta());
    error_ils[i] = test::relative_error(ils.theta, true_theta());
  }
  std::printf("noise-free relative error  Ts=0.02: TOCLS %s TOCILS %s;  "
              "Ts=0.01: %s %s\n",
              test::scientific(error_ls[0]).c_str(),
              test::scientific(error_ils[0]).c_str(),
              test::scientific(error_ls[1]).c_str(),
              test::scientific(error_ils[1]).c_str());
  EXPECT_LT(error_ls[0], 1e-2);
  // Second order in Ts: a ratio of 4 expected, 2.5 allowed.
  EXPECT_GT(error_ls[0] / error_ls[1], 2.5);
  EXPECT_LT(error_ils[0], 1e-10);
  EXPECT_LT(error_ils[1], 1e-10);
}

// Noise on both signals (SNR 10 dB each; white Gaussian on the input,
// coloured on the output), 30 runs of 5000 samples at Ts = 0.1: TOCILS's
// mean is within 3 standard errors of the truth on every parameter, while
// LSSVF's is biased (the input noise enters its regressors).
TEST(CumulantEiv, ConsistentWhereLeastSquaresIsBiased) {
  const int runs = 30, n = 5000;
  const double ts = 0.1;
  CumulantEivSettings<double> settings;
  settings.lags = 50;
  Eigen::MatrixXd ils(runs, 4), ls(runs, 4);
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  for (int r = 0; r < runs; ++r) {
    const auto u0 = skewed_input(n, 100 + r);
    const auto y0 = plant_output(u0, ts);
    double sd_y0 = 0;
    for (double v : y0) sd_y0 += v * v;
    sd_y0 = std::sqrt(sd_y0 / n);
    const double su = 1.0 / std::sqrt(10.0), sy = sd_y0 / std::sqrt(10.0);
    std::vector<double> u(n), y(n);
    double coloured = 0;
    for (int k = 0; k < n; ++k) {
      u[k] = u0[k] + su * normal(rng);
      coloured = -0.8 * coloured + 0.6 * normal(rng);  // sd ~ 1
      y[k] = y0[k] + sy * coloured;
    }
    CumulantEivEstimate<double> est;
    Status status = tocils(kOrders, svf_with(3), view(y, u, ts), settings,
                           &est);
    ASSERT_TRUE(status.ok()) << status.message();
    ils.row(r) = est.theta.transpose();
    OfflineEstimate<double> lsest;
    status = lssvf(kOrders, svf_with(3), view(y, u, ts), &lsest);
    ASSERT_TRUE(status.ok()) << status.message();
    ls.row(r) = lsest.theta.transpose();
  }
  const Eigen::VectorXd theta = true_theta();
  const Eigen::VectorXd ils_mean = ils.colwise().mean().transpose();
  const Eigen::VectorXd ls_mean = ls.colwise().mean().transpose();
  double ls_worst = 0;
  for (int i = 0; i < 4; ++i) {
    const double ils_se =
        std::sqrt((ils.col(i).array() - ils_mean(i)).square().sum() /
                  (runs - 1) / runs);
    const double ls_se =
        std::sqrt((ls.col(i).array() - ls_mean(i)).square().sum() /
                  (runs - 1) / runs);
    const double ils_z = std::abs(ils_mean(i) - theta(i)) / ils_se;
    const double ls_z = std::abs(ls_mean(i) - theta(i)) / ls_se;
    std::printf("theta(%d) = %5.2f: TOCILS mean %.4f (%.1f se off), LSSVF "
                "mean %.4f (%.1f se off)\n",
                i, theta(i), ils_mean(i), ils_z, ls_mean(i), ls_z);
    EXPECT_LT(ils_z, 3.0) << i;
    ls_worst = std::max(ls_worst, ls_z);
  }
  EXPECT_GT(ls_worst, 3.0);
}

TEST(CumulantEiv, RefusesWhatItCannotUse) {
  const double ts = 0.05;
  const auto u = skewed_input(2000, 5);
  const auto y = plant_output(u, ts);
  CumulantEivSettings<double> settings;
  CumulantEivEstimate<double> est;
  // A symmetric (binary, balanced) input has no third-order cumulants.
  std::vector<double> binary(2000);
  for (int k = 0; k < 2000; ++k) binary[k] = ((k / 7) % 2) ? 1.0 : -1.0;
  Status status =
      tocls(kOrders, svf_with(3), view(y, binary, ts), settings, &est);
  EXPECT_EQ(status.code(), ErrorCode::kBadInput);
  EXPECT_NE(status.message().find("skewed"), std::string::npos)
      << status.message();
  // Fewer lags than parameters, and more than half the record.
  settings.lags = 3;
  EXPECT_EQ(tocls(kOrders, svf_with(3), view(y, u, ts), settings, &est).code(),
            ErrorCode::kBadInput);
  settings.lags = 1001;
  EXPECT_EQ(tocls(kOrders, svf_with(3), view(y, u, ts), settings, &est).code(),
            ErrorCode::kBadInput);
  settings.lags = 50;
  // Irregular instants.
  std::vector<double> t(2000);
  for (int k = 0; k < 2000; ++k) t[k] = k * ts + (k % 3) * 0.01;
  RecordView<double> irregular = view(y, u, ts);
  irregular.instants = t.data();
  EXPECT_EQ(tocils(kOrders, svf_with(3), irregular, settings, &est).code(),
            ErrorCode::kBadInput);
  // No place for the estimate.
  CumulantEivEstimate<double>* nowhere = nullptr;
  EXPECT_EQ(
      tocls(kOrders, svf_with(3), view(y, u, ts), settings, nowhere).code(),
      ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
