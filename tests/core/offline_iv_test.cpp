// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/offline_iv.hpp: identities of the QR-based
// IV solution, recovery of noise-free LTI systems (open and closed loop),
// consistency and covariance of SRIVC against a Monte Carlo run, and input
// validation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ctid/offline/least_squares.hpp"
#include "ctid/simulation/ltv_simulator.hpp"
#include "ctid/offline/refined_iv.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

using test::binary_input;

using test::MatrixNear;
using test::relative_error;

ParameterTrajectory<double> constant(const Eigen::VectorXd& theta) {
  return [theta](double, Eigen::VectorXd& out) { out = theta; };
}

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

// Noise-free open-loop output x of the LTI model theta, from rest.
std::vector<double> simulate_open_loop(const ModelOrders& orders,
                                       const Eigen::VectorXd& theta,
                                       const std::vector<double>& u,
                                       double ts) {
  LtvSimulationConfig<double> config;
  config.orders = orders;
  LtvSimulator<double> sim;
  EXPECT_TRUE(sim.configure(config).ok());
  std::vector<double> x(u.size());
  SimulationOutputs<double> out;
  out.x = x.data();
  EXPECT_TRUE(
      sim.simulate(constant(theta), view(u, u, ts), nullptr, nullptr, out)
          .ok());
  return x;
}

// Closed loop u = r1 + C(r2 - y), y = x + e: fills y and the plant input u.
void simulate_closed_loop(const ModelOrders& orders,
                          const Eigen::VectorXd& theta,
                          const DiscreteTransferFunction<double>& controller,
                          const std::vector<double>& r1,
                          const std::vector<double>& r2,
                          const std::vector<double>* noise, double ts,
                          std::vector<double>& y, std::vector<double>& u) {
  LtvSimulationConfig<double> config;
  config.orders = orders;
  config.closed_loop = true;
  config.controller = controller;
  LtvSimulator<double> sim;
  ASSERT_TRUE(sim.configure(config).ok());
  y.assign(r1.size(), 0.0);
  u.assign(r1.size(), 0.0);
  SimulationOutputs<double> out;
  out.y = y.data();
  out.u_applied = u.data();
  ASSERT_TRUE(sim.simulate(constant(theta), view(r1, r1, ts), r2.data(),
                           noise ? noise->data() : nullptr, out)
                  .ok());
}

// The system of the consistency tests: (p^2 + 1.2 p + 2) x = 2 u.
const ModelOrders kOrders = siso_orders(2, 1, 0);
Eigen::VectorXd true_theta() { return Eigen::Vector3d(1.2, 2.0, 2.0); }

SvfSettings<double> svf_with(double lambda) {
  SvfSettings<double> svf;
  svf.lambda_svf = lambda;
  return svf;
}

// ---------------------------------------------------------------------------
// Identities of the solution.

// LSSVF is the least-squares solution of the SVF regression (the same as
// solve_least_squares), with covariance sigma^2 (Phi^T Phi)^-1.
TEST(OfflineIv, LssvfIsLeastSquaresOfTheSvfRegression) {
  const double ts = 0.05;
  const auto u = binary_input(1500, 10, 3);
  auto y = simulate_open_loop(kOrders, true_theta(), u, ts);
  std::mt19937 rng(4);
  std::normal_distribution<double> normal;
  for (auto& v : y) v += 0.2 * normal(rng);
  const SvfSettings<double> svf = svf_with(2);
  OfflineEstimate<double> est;
  ASSERT_TRUE(lssvf(kOrders, svf, view(y, u, ts), &est).ok());

  Eigen::MatrixXd Phi;
  Eigen::VectorXd target, theta_ls;
  ASSERT_TRUE(
      build_svf_regression(kOrders, svf, view(y, u, ts), Phi, target).ok());
  ASSERT_TRUE(solve_least_squares<double>(Phi, target, theta_ls).ok());
  EXPECT_TRUE(MatrixNear(est.theta, theta_ls, 1e-12));
  const double sigma2 = (target - Phi * theta_ls).squaredNorm() /
                        static_cast<double>(Phi.rows() - Phi.cols());
  const Eigen::MatrixXd normal_cov = sigma2 * (Phi.transpose() * Phi).inverse();
  // The normal equations lose ~cond(Phi)^2 eps; cond(Phi) is ~10 here.
  EXPECT_TRUE(MatrixNear(est.covariance / normal_cov.norm(),
                         normal_cov / normal_cov.norm(), 1e-10));
  EXPECT_EQ(est.iterations, 1);
  EXPECT_TRUE(est.converged);
}

// The QR route (Q^T Phi) theta = Q^T Y gives the textbook IV solution
// (Z^T Phi)^-1 Z^T Y, and R gives (Z^T Z)^-1.
TEST(OfflineIv, QrSolutionEqualsTheNormalEquationIv) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  const int n = 200, np = 3;
  Eigen::MatrixXd Z(n, np), Phi(n, np);
  Eigen::VectorXd target(n);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < np; ++i) {
      Z(k, i) = normal(rng);
      Phi(k, i) = Z(k, i) + 0.5 * normal(rng);
    }
    target(k) = normal(rng);
  }
  offline_iv_detail::IvSolution<double> solution;
  ASSERT_TRUE(offline_iv_detail::solve_iv<double>(Z, Phi, target, "instrument",
                                                  solution)
                  .ok());
  const Eigen::VectorXd textbook =
      (Z.transpose() * Phi).inverse() * (Z.transpose() * target);
  EXPECT_TRUE(MatrixNear(solution.theta, textbook, 1e-12));
  EXPECT_TRUE(
      MatrixNear(solution.inverse_gram, (Z.transpose() * Z).inverse(), 1e-12));
  const Eigen::MatrixXd zp_inv = (Z.transpose() * Phi).inverse();
  EXPECT_TRUE(MatrixNear(solution.sandwich,
                         zp_inv * (Z.transpose() * Z) * zp_inv.transpose(),
                         1e-12));
}

// The adaptive-prefilter regression, given the SVF denominator and gain,
// is the SVF regression (same layout, eq. 1.27, same rules).
TEST(OfflineIv, PrefilteredRegressionWithSvfDenominatorIsTheSvfRegression) {
  const double ts = 0.05;
  const ModelOrders orders = siso_orders(3, 2, 2);
  const auto u = binary_input(400, 5, 6);
  const auto y = simulate_open_loop(
      orders, (Eigen::VectorXd(5) << 3, 4, 2, 0.5, 2).finished(), u, ts);
  const SvfSettings<double> svf = svf_with(1.5);
  Eigen::MatrixXd Phi, Phi_svf;
  Eigen::VectorXd target, target_svf;
  ASSERT_TRUE(
      build_svf_regression(orders, svf, view(y, u, ts), Phi_svf, target_svf)
          .ok());
  offline_iv_detail::build_prefiltered_regression<double>(
      orders, svf_denominator<double>(3, 1.5), svf_gain<double>(3, 1.5, true),
      svf.y_intersample, svf.u_intersample, view(y, u, ts), Phi, target);
  EXPECT_TRUE(MatrixNear(Phi, Phi_svf, 1e-14));
  EXPECT_TRUE(MatrixNear(target, target_svf, 1e-14));
}

// An unstable estimate drives the prefilter and the auxiliary model with its
// roots reflected: p^2 - p + 2 becomes p^2 + p + 2; b is kept.
TEST(OfflineIv, UnstableIterateIsReflected) {
  Eigen::VectorXd drive;
  ASSERT_TRUE(offline_iv_detail::stabilised<double>(
                  kOrders, Eigen::Vector3d(-1, 2, 5), drive)
                  .ok());
  EXPECT_TRUE(MatrixNear(drive, Eigen::Vector3d(1, 2, 5), 1e-12));
}

// ---------------------------------------------------------------------------
// Noise-free LTI records. u is ZOH and its ZOH filter is exact; y is
// filtered by the trapezoidal rule, whose map warps a frequency w by
// (w Ts)^2 / 12: over the band of the record (w up to a few rad/s) at
// Ts = 0.01 that is ~1e-4 of the filtered signals, so LSSVF and IVSVF carry
// relative errors of O(1e-4) that scale as Ts^2 (measured: 3.2e-5 at
// Ts = 0.01, 7.9e-6 at 0.005, a ratio of 4.0).
// SRIVC (and CLSRIVC) at the true theta is exact whatever the rule: with
// D = A the top filter output is p^na F y = g (y - sum a_i p^(na-i) F y) by
// construction, so y_f^(na) + sum a_i y_f^(na-i) = g y holds sample by
// sample, and g y = g x_hat = B(p) F u with exact ZOH filtering of u. The
// true theta solves the filtered regression exactly and SRIVC stops there,
// to rounding (measured 2.6e-14).

struct NoiseFreeErrors {
  double ls, iv, sriv;
};

NoiseFreeErrors noise_free_open_loop_errors(double ts, double duration) {
  const int n = static_cast<int>(duration / ts);
  const int hold = static_cast<int>(0.5 / ts);
  const auto u = binary_input(n, hold, 7);
  const auto y = simulate_open_loop(kOrders, true_theta(), u, ts);
  const SvfSettings<double> svf = svf_with(2);
  OfflineEstimate<double> ls, iv, sriv;
  EXPECT_TRUE(lssvf(kOrders, svf, view(y, u, ts), &ls).ok());
  EXPECT_TRUE(ivsvf(kOrders, svf, view(y, u, ts), &iv).ok());
  const Status status =
      srivc(kOrders, svf, SrivcSettings<double>(), view(y, u, ts), &sriv);
  EXPECT_TRUE(status.ok()) << status.message();
  EXPECT_TRUE(sriv.converged);
  return {relative_error(ls.theta, true_theta()),
          relative_error(iv.theta, true_theta()),
          relative_error(sriv.theta, true_theta())};
}

TEST(OfflineIv, NoiseFreeOpenLoopRecordIsRecovered) {
  const NoiseFreeErrors coarse = noise_free_open_loop_errors(0.01, 40);
  const NoiseFreeErrors fine = noise_free_open_loop_errors(0.005, 40);
  std::printf(
      "noise-free open loop, relative error  Ts=0.01: LSSVF %s IVSVF %s SRIVC "
      "%s;  Ts=0.005: %s %s %s\n",
      test::scientific(coarse.ls).c_str(), test::scientific(coarse.iv).c_str(),
      test::scientific(coarse.sriv).c_str(), test::scientific(fine.ls).c_str(),
      test::scientific(fine.iv).c_str(), test::scientific(fine.sriv).c_str());
  EXPECT_LT(coarse.ls, 1e-4);
  EXPECT_LT(coarse.iv, 1e-4);
  // Second order in Ts: a ratio of 4 expected, 3 allowed for the
  // higher-order terms.
  EXPECT_GT(coarse.ls / fine.ls, 3);
  EXPECT_GT(coarse.iv / fine.iv, 3);
  // Exact fixed point: rounding in ~10^4 filter steps, cond ~10.
  EXPECT_LT(coarse.sriv, 1e-11);
  EXPECT_LT(fine.sriv, 1e-11);
}

// A zero, a delay of 3 samples and a FOH input (simulated exactly as
// piecewise linear, filtered by the exact first-order hold): IVSVF keeps
// the O(Ts^2) error of the trapezoidal filtering of y (measured 7.7e-5 at
// Ts = 0.01), SRIVC, which filters y by the model, is exact.
TEST(OfflineIv, NoiseFreeRecordWithZeroDelayAndFohInput) {
  const double ts = 0.01;
  const ModelOrders orders = siso_orders(2, 2, 3);
  const Eigen::VectorXd theta = Eigen::Vector4d(1.2, 2.0, 0.5, 2.0);
  std::vector<double> u = binary_input(4000, 50, 8);
  // Smooth the steps so that the piecewise-linear input is a fair FOH.
  for (std::size_t k = 1; k < u.size(); ++k) u[k] = 0.9 * u[k - 1] + 0.1 * u[k];
  LtvSimulationConfig<double> config;
  config.orders = orders;
  config.u_intersample = InterSample::kFoh;
  LtvSimulator<double> sim;
  ASSERT_TRUE(sim.configure(config).ok());
  std::vector<double> y(u.size());
  SimulationOutputs<double> out;
  out.x = y.data();
  ASSERT_TRUE(
      sim.simulate(constant(theta), view(u, u, ts), nullptr, nullptr, out)
          .ok());
  SvfSettings<double> svf = svf_with(2);
  svf.u_intersample = InterSample::kFoh;
  OfflineEstimate<double> iv, sriv;
  ASSERT_TRUE(ivsvf(orders, svf, view(y, u, ts), &iv).ok());
  const Status status =
      srivc(orders, svf, SrivcSettings<double>(), view(y, u, ts), &sriv);
  ASSERT_TRUE(status.ok()) << status.message();
  const double e_iv = relative_error(iv.theta, theta);
  const double e_sriv = relative_error(sriv.theta, theta);
  std::printf(
      "noise-free, zero + delay + FOH, Ts=0.01: IVSVF %s SRIVC %s (%d "
      "iterations)\n",
      test::scientific(e_iv).c_str(), test::scientific(e_sriv).c_str(),
      sriv.iterations);
  EXPECT_LT(e_iv, 1e-4);
  EXPECT_LT(e_sriv, 1e-4);
}

// A converged SRIVC estimate is a fixed point: restarted from it, SRIVC
// stops after one iteration at the same estimate.
TEST(OfflineIv, SrivcEstimateIsAFixedPoint) {
  const double ts = 0.05;
  const auto u = binary_input(2000, 10, 9);
  auto y = simulate_open_loop(kOrders, true_theta(), u, ts);
  std::mt19937 rng(10);
  std::normal_distribution<double> normal;
  for (auto& v : y) v += 0.3 * normal(rng);
  SrivcSettings<double> settings;
  settings.tolerance = 1e-10;
  settings.max_iterations = 100;
  OfflineEstimate<double> first, again;
  ASSERT_TRUE(
      srivc(kOrders, svf_with(2), settings, view(y, u, ts), &first).ok());
  settings.theta_init = first.theta;
  ASSERT_TRUE(
      srivc(kOrders, svf_with(2), settings, view(y, u, ts), &again).ok());
  EXPECT_EQ(again.iterations, 1);
  EXPECT_TRUE(MatrixNear(again.theta, first.theta, 1e-9));
}

// Closed loop with a PI controller, r2 a binary set point, no noise; without
// and with an input delay (u_hat is then delayed like u).
TEST(OfflineIv, NoiseFreeClosedLoopRecordIsRecovered) {
  const double ts = 0.01;
  const int n = 4000;
  const auto controller = pid_backward_euler<double>(1.0, 0.5, 0.0, ts);
  const std::vector<double> r1(n, 0.0);
  const auto r2 = binary_input(n, 100, 11);
  for (int nk : {0, 2}) {
    const ModelOrders orders = siso_orders(2, 1, nk);
    std::vector<double> y, u;
    simulate_closed_loop(orders, true_theta(), controller, r1, r2, nullptr, ts,
                         y, u);
    OfflineEstimate<double> est;
    const Status status =
        clsrivc(orders, svf_with(2), SrivcSettings<double>(), view(y, u, ts),
                r1.data(), r2.data(), controller, &est);
    ASSERT_TRUE(status.ok()) << status.message();
    const double error = relative_error(est.theta, true_theta());
    std::printf(
        "noise-free closed loop, nk=%d, Ts=0.01: CLSRIVC relative "
        "error %s (%d iterations)\n",
        nk, test::scientific(error).c_str(), est.iterations);
    // Exact as in open loop (see above): u_hat = u and x_hat = y at the
    // truth.
    EXPECT_LT(error, 1e-11) << "nk = " << nk;
  }
}

// Irregular sampling (intervals uniform in [0.5, 1.5] Ts) and two inputs,
// one with a zero: the filters are rediscretised at every interval and the
// exact fixed point of SRIVC survives (measured 4.9e-14; LSSVF 4.0e-5).
TEST(OfflineIv, NoiseFreeIrregularTwoInputRecordIsRecovered) {
  const double ts = 0.01;
  const int n = 4000;
  ModelOrders orders;
  orders.na = 2;
  orders.nb = {1, 2};
  orders.nk = {0, 0};
  const Eigen::VectorXd theta =
      (Eigen::VectorXd(5) << 1.2, 2.0, 2.0, 0.5, 1.0).finished();
  std::vector<double> instants(n);
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> spread(0.5, 1.5);
  instants[0] = 0;
  for (int k = 1; k < n; ++k) instants[k] = instants[k - 1] + ts * spread(rng);
  std::vector<double> u = binary_input(n, 50, 21);
  const auto u2 = binary_input(n, 70, 22);
  u.insert(u.end(), u2.begin(), u2.end());  // column-major N-by-2
  std::vector<double> y(n);
  RecordView<double> record;
  record.y = y.data();
  record.u = u.data();
  record.num_samples = n;
  record.num_inputs = 2;
  record.instants = instants.data();
  LtvSimulationConfig<double> config;
  config.orders = orders;
  LtvSimulator<double> sim;
  ASSERT_TRUE(sim.configure(config).ok());
  SimulationOutputs<double> out;
  out.x = y.data();
  ASSERT_TRUE(
      sim.simulate(constant(theta), record, nullptr, nullptr, out).ok());
  OfflineEstimate<double> ls, sriv;
  ASSERT_TRUE(lssvf(orders, svf_with(2), record, &ls).ok());
  const Status status =
      srivc(orders, svf_with(2), SrivcSettings<double>(), record, &sriv);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_LT(relative_error(ls.theta, theta), 1e-4);  // Tustin, as above
  EXPECT_LT(relative_error(sriv.theta, theta), 1e-11);
}

// ---------------------------------------------------------------------------
// Monte Carlo: 40 noise realisations on one input (Ts = 0.05, 4000 samples,
// binary input held 10 samples), SNR 10 dB. About 1 s in a Release build.

struct MonteCarlo {
  static constexpr int kRuns = 40;
  Eigen::MatrixXd ls, sriv;  // runs x np
  Eigen::MatrixXd mean_sriv_covariance;
  double mean_iterations = 0;
};

const MonteCarlo& monte_carlo() {
  static const MonteCarlo result = [] {
    const double ts = 0.05;
    const int n = 4000;
    const auto u = binary_input(n, 10, 12);
    const auto x = simulate_open_loop(kOrders, true_theta(), u, ts);
    const double sigma = noise_scale_for_snr(x.data(), n, 10.0);
    std::mt19937 rng(13);
    std::normal_distribution<double> normal;
    MonteCarlo mc;
    const int np = kOrders.num_parameters();
    mc.ls.resize(MonteCarlo::kRuns, np);
    mc.sriv.resize(MonteCarlo::kRuns, np);
    mc.mean_sriv_covariance = Eigen::MatrixXd::Zero(np, np);
    for (int run = 0; run < MonteCarlo::kRuns; ++run) {
      std::vector<double> y(x);
      for (auto& v : y) v += sigma * normal(rng);
      OfflineEstimate<double> ls, sriv;
      EXPECT_TRUE(lssvf(kOrders, svf_with(2), view(y, u, ts), &ls).ok());
      const Status status = srivc(kOrders, svf_with(2), SrivcSettings<double>(),
                                  view(y, u, ts), &sriv);
      EXPECT_TRUE(status.ok()) << status.message();
      mc.ls.row(run) = ls.theta.transpose();
      mc.sriv.row(run) = sriv.theta.transpose();
      mc.mean_sriv_covariance += sriv.covariance / MonteCarlo::kRuns;
      mc.mean_iterations += double(sriv.iterations) / MonteCarlo::kRuns;
    }
    return mc;
  }();
  return result;
}

Eigen::VectorXd column_mean(const Eigen::MatrixXd& m) {
  return m.colwise().mean().transpose();
}
Eigen::VectorXd column_std(const Eigen::MatrixXd& m) {
  const Eigen::MatrixXd centred = m.rowwise() - m.colwise().mean();
  return (centred.colwise().squaredNorm() / double(m.rows() - 1))
      .cwiseSqrt()
      .transpose();
}

// SRIVC is consistent: its mean lies within 3 standard errors of the truth
// (parameter by parameter); LSSVF is biased by the correlation of phi_f with
// the filtered noise: at least one mean lies outside 3 standard errors.
TEST(OfflineIv, SrivcIsUnbiasedWhereLssvfIsBiased) {
  const MonteCarlo& mc = monte_carlo();
  const Eigen::VectorXd theta = true_theta();
  const double root_runs = std::sqrt(double(MonteCarlo::kRuns));
  const Eigen::VectorXd sriv_mean = column_mean(mc.sriv);
  const Eigen::VectorXd sriv_se = column_std(mc.sriv) / root_runs;
  const Eigen::VectorXd ls_mean = column_mean(mc.ls);
  const Eigen::VectorXd ls_se = column_std(mc.ls) / root_runs;
  const Eigen::VectorXd sriv_z =
      (sriv_mean - theta).cwiseAbs().cwiseQuotient(sriv_se);
  const Eigen::VectorXd ls_z =
      (ls_mean - theta).cwiseAbs().cwiseQuotient(ls_se);
  for (int i = 0; i < theta.size(); ++i) {
    std::printf(
        "theta(%d) = %.3f: SRIVC mean %.4f (se %.4f, %.1f se off), LSSVF mean "
        "%.4f (se %.4f, %.1f se off)\n",
        i, theta(i), sriv_mean(i), sriv_se(i), sriv_z(i), ls_mean(i), ls_se(i),
        ls_z(i));
  }
  std::printf("SRIVC mean iterations %.1f\n", mc.mean_iterations);
  EXPECT_LT(sriv_z.maxCoeff(), 3.0);
  EXPECT_GT(ls_z.maxCoeff(), 3.0);
}

// The SRIVC covariance noise_variance (sum zeta_f zeta_f^T)^-1 matches the
// Monte Carlo variance within a factor 2. 40 runs estimate a variance to
// +-23% at one sigma (sqrt(2/39)); the measured ratios here are 1.4-1.5,
// and 0.82-1.10 with 200 runs (same input and seed), so the excess is
// sampling error of the first runs, not a biased formula. A missing a_na^2
// (the unit-gain prefilter) would show as a ratio of 1/4.
TEST(OfflineIv, SrivcCovarianceMatchesMonteCarloSpread) {
  const MonteCarlo& mc = monte_carlo();
  const Eigen::VectorXd mc_var = column_std(mc.sriv).array().square();
  const Eigen::VectorXd reported = mc.mean_sriv_covariance.diagonal();
  for (int i = 0; i < mc_var.size(); ++i) {
    const double ratio = reported(i) / mc_var(i);
    std::printf("theta(%d): reported variance %s, Monte Carlo %s, ratio %.2f\n",
                i, test::scientific(reported(i)).c_str(),
                test::scientific(mc_var(i)).c_str(), ratio);
    EXPECT_GT(ratio, 0.5) << i;
    EXPECT_LT(ratio, 2.0) << i;
  }
}

// Closed loop with noise: 40 runs of the PI loop above (Ts = 0.05, 4000
// samples, r2 binary held 10 samples), SNR 10 dB at the plant output.
// CLSRIVC is consistent where LSSVF is not (feedback and filtering both
// correlate phi_f with the noise), and its reported covariance matches the
// spread within a factor 2. Measured here: 1.4, 0.2, 2.1 standard errors
// off, variance ratios 1.44, 1.06, 1.54; with 400 runs of the same seeds
// 1.1, 0.9, 0.3 standard errors and reported/Monte Carlo standard
// deviations 0.0125/0.0125, 0.0114/0.0109, 0.0145/0.0148, so the 40-run
// figures are sampling error. With this white noise, open-loop SRIVC on the
// same data is consistent too (its instruments at t_k see e only up to t_(k-1)
// and its filtered equation error is e itself); it is not tested here.
TEST(OfflineIv, ClsrivcIsUnbiasedOnNoisyClosedLoopData) {
  const double ts = 0.05;
  const int n = 4000, runs = 40;
  const auto controller = pid_backward_euler<double>(1.0, 0.5, 0.0, ts);
  const std::vector<double> r1(n, 0.0);
  const auto r2 = binary_input(n, 10, 18);
  std::vector<double> x, u;
  simulate_closed_loop(kOrders, true_theta(), controller, r1, r2, nullptr, ts,
                       x, u);
  const double sigma = noise_scale_for_snr(x.data(), n, 10.0);
  std::mt19937 rng(19);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd ls(runs, 3), cl(runs, 3);
  Eigen::Vector3d reported = Eigen::Vector3d::Zero();
  for (int run = 0; run < runs; ++run) {
    std::vector<double> e(n), y;
    for (auto& v : e) v = sigma * normal(rng);
    simulate_closed_loop(kOrders, true_theta(), controller, r1, r2, &e, ts, y,
                         u);
    OfflineEstimate<double> a, b;
    ASSERT_TRUE(lssvf(kOrders, svf_with(2), view(y, u, ts), &a).ok());
    const Status status =
        clsrivc(kOrders, svf_with(2), SrivcSettings<double>(), view(y, u, ts),
                r1.data(), r2.data(), controller, &b);
    ASSERT_TRUE(status.ok()) << status.message();
    ls.row(run) = a.theta.transpose();
    cl.row(run) = b.theta.transpose();
    reported += b.covariance.diagonal() / runs;
  }
  const Eigen::VectorXd theta = true_theta();
  const double root_runs = std::sqrt(double(runs));
  const Eigen::VectorXd cl_sd = column_std(cl);
  const Eigen::VectorXd cl_z =
      (column_mean(cl) - theta).cwiseAbs().cwiseQuotient(cl_sd / root_runs);
  const Eigen::VectorXd ls_z = (column_mean(ls) - theta)
                                   .cwiseAbs()
                                   .cwiseQuotient(column_std(ls) / root_runs);
  for (int i = 0; i < 3; ++i) {
    const double ratio = reported(i) / (cl_sd(i) * cl_sd(i));
    std::printf(
        "closed loop theta(%d): CLSRIVC %.1f se off, variance ratio %.2f; "
        "LSSVF %.1f se off\n",
        i, cl_z(i), ratio, ls_z(i));
    EXPECT_GT(ratio, 0.5) << i;
    EXPECT_LT(ratio, 2.0) << i;
  }
  EXPECT_LT(cl_z.maxCoeff(), 3.0);
  EXPECT_GT(ls_z.maxCoeff(), 3.0);
}

// ---------------------------------------------------------------------------
// Non-convergence and validation.

TEST(OfflineIv, MaxIterationsReachedIsNotConvergedWithTheLastIterate) {
  const double ts = 0.05;
  const auto u = binary_input(2000, 10, 14);
  auto y = simulate_open_loop(kOrders, true_theta(), u, ts);
  std::mt19937 rng(15);
  std::normal_distribution<double> normal;
  for (auto& v : y) v += 0.3 * normal(rng);
  // A poor start (SVF cut-off 25 for a system at 2 rad/s), so that one
  // refined-IV step cannot reach a stationary loss: with a good start one
  // step already passes the engine's score test (converged).
  const double lambda = 25;
  SrivcSettings<double> settings;
  settings.max_iterations = 1;
  OfflineEstimate<double> est;
  const Status status =
      srivc(kOrders, svf_with(lambda), settings, view(y, u, ts), &est);
  EXPECT_EQ(status.code(), ErrorCode::kNotConverged) << status.message();
  EXPECT_FALSE(est.converged);
  EXPECT_EQ(est.iterations, 1);
  ASSERT_EQ(est.theta.size(), 3);
  EXPECT_TRUE(est.theta.allFinite());
  EXPECT_TRUE(est.covariance.allFinite());
  // The one iterate is a refined-IV step away from the start.
  OfflineEstimate<double> start;
  ASSERT_TRUE(ivsvf(kOrders, svf_with(lambda), view(y, u, ts), &start).ok());
  EXPECT_GT(relative_error(est.theta, start.theta), 1e-6);
}

class OfflineIvValidation : public ::testing::Test {
 protected:
  void SetUp() override {
    u = binary_input(200, 10, 16);
    y = simulate_open_loop(kOrders, true_theta(), u, ts);
    r1.assign(u.size(), 0.0);
    r2 = u;
    controller = pid_backward_euler<double>(1.0, 0.5, 0.0, ts);
  }
  Status run_srivc(const ModelOrders& orders, const SvfSettings<double>& svf,
                   const SrivcSettings<double>& settings,
                   const RecordView<double>& record) {
    OfflineEstimate<double> est;
    return srivc(orders, svf, settings, record, &est);
  }
  Status run_clsrivc(const SvfSettings<double>& svf, const double* p1,
                     const double* p2,
                     const DiscreteTransferFunction<double>& c) {
    OfflineEstimate<double> est;
    return clsrivc(kOrders, svf, SrivcSettings<double>(), view(y, u, ts), p1,
                   p2, c, &est);
  }
  const double ts = 0.05;
  std::vector<double> u, y, r1, r2;
  DiscreteTransferFunction<double> controller;
};

TEST_F(OfflineIvValidation, BadOrdersAndRecord) {
  const SvfSettings<double> svf = svf_with(2);
  const SrivcSettings<double> settings;
  EXPECT_EQ(
      run_srivc(siso_orders(0, 1, 0), svf, settings, view(y, u, ts)).code(),
      ErrorCode::kBadInput);
  EXPECT_EQ(
      run_srivc(siso_orders(2, 4, 0), svf, settings, view(y, u, ts)).code(),
      ErrorCode::kBadInput);
  ModelOrders two_inputs = kOrders;
  two_inputs.nb = {1, 1};
  two_inputs.nk = {0, 0};
  EXPECT_EQ(run_srivc(two_inputs, svf, settings, view(y, u, ts)).code(),
            ErrorCode::kDimensionMismatch);
  RecordView<double> short_record = view(y, u, ts);
  short_record.num_samples = 2;
  EXPECT_EQ(run_srivc(kOrders, svf, settings, short_record).code(),
            ErrorCode::kBadInput);
  std::vector<double> y_nan = y;
  y_nan[17] = NAN;
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y_nan, u, ts)).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y, u, 0.0)).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(run_srivc(kOrders, svf_with(-1), settings, view(y, u, ts)).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(srivc(kOrders, svf, settings, view(y, u, ts),
                  static_cast<OfflineEstimate<double>*>(nullptr))
                .code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(lssvf(kOrders, svf, view(y_nan, u, ts),
                  static_cast<OfflineEstimate<double>*>(nullptr))
                .code(),
            ErrorCode::kBadInput);
  OfflineEstimate<double> est;
  EXPECT_EQ(ivsvf(siso_orders(0, 1, 0), svf, view(y, u, ts), &est).code(),
            ErrorCode::kBadInput);
}

TEST_F(OfflineIvValidation, BadSrivcSettings) {
  const SvfSettings<double> svf = svf_with(2);
  SrivcSettings<double> settings;
  settings.tolerance = 0;
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y, u, ts)).code(),
            ErrorCode::kBadInput);
  settings.tolerance = NAN;
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y, u, ts)).code(),
            ErrorCode::kBadInput);
  settings = SrivcSettings<double>();
  settings.max_iterations = 0;
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y, u, ts)).code(),
            ErrorCode::kBadInput);
  settings = SrivcSettings<double>();
  settings.theta_init = Eigen::Vector2d(1, 2);
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y, u, ts)).code(),
            ErrorCode::kDimensionMismatch);
  settings.theta_init = Eigen::Vector3d(-1, 2, 2);  // p^2 - p + 2
  const Status unstable = run_srivc(kOrders, svf, settings, view(y, u, ts));
  EXPECT_EQ(unstable.code(), ErrorCode::kBadInput);
  EXPECT_NE(unstable.message().find("stable"), std::string::npos);
  settings.theta_init = Eigen::Vector3d(1, NAN, 2);
  EXPECT_EQ(run_srivc(kOrders, svf, settings, view(y, u, ts)).code(),
            ErrorCode::kBadInput);
}

TEST_F(OfflineIvValidation, BadClosedLoopArguments) {
  const SvfSettings<double> svf = svf_with(2);
  EXPECT_EQ(run_clsrivc(svf, nullptr, r2.data(), controller).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(run_clsrivc(svf, r1.data(), nullptr, controller).code(),
            ErrorCode::kBadInput);
  std::vector<double> r2_nan = r2;
  r2_nan[5] = INFINITY;
  EXPECT_EQ(run_clsrivc(svf, r1.data(), r2_nan.data(), controller).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(
      run_clsrivc(svf, r1.data(), r2.data(), DiscreteTransferFunction<double>())
          .code(),
      ErrorCode::kBadInput);
  SvfSettings<double> foh = svf;
  foh.u_intersample = InterSample::kFoh;
  EXPECT_EQ(run_clsrivc(foh, r1.data(), r2.data(), controller).code(),
            ErrorCode::kBadInput);
}

// A zero input cannot excite the numerator: a numerical failure that names
// persistent excitation, from every method.
TEST_F(OfflineIvValidation, UnexcitedRecordIsANumericalFailure) {
  const std::vector<double> zero(u.size(), 0.0);
  std::vector<double> noise(u.size());
  std::mt19937 rng(17);
  std::normal_distribution<double> normal;
  for (auto& v : noise) v = normal(rng);
  const RecordView<double> record = view(noise, zero, ts);
  OfflineEstimate<double> est;
  for (const Status& status :
       {lssvf(kOrders, svf_with(2), record, &est),
        ivsvf(kOrders, svf_with(2), record, &est),
        srivc(kOrders, svf_with(2), SrivcSettings<double>(), record, &est)}) {
    EXPECT_EQ(status.code(), ErrorCode::kNumericalFailure);
    EXPECT_NE(status.message().find("persistently exciting"), std::string::npos)
        << status.message();
  }
}

}  // namespace
}  // namespace ctid
