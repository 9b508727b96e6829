// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/refined_iv_bj.hpp: the ARMA estimator
// against known ARMA processes (estimate within its reported standard errors;
// the pure AR case equals the least-squares solution), the discrete filter
// against a direct recursion, and exact recovery of a continuous plant from
// noise-free records by RIVC (open loop, fractional delay), CLRIVC and
// CL2SRIVC. The records are simulated independently: controllable
// canonical state space, exact ZOH step by the matrix exponential.
#include "ctid/offline/refined_iv_bj.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_util.hpp"

namespace ctid {
namespace {

using test::binary_input;
using test::relative_error;
using test::simulate_zoh;

std::vector<double> arma_process(const Eigen::VectorXd& c,
                                 const Eigen::VectorXd& d, int n, double sd,
                                 unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0, sd);
  std::vector<double> e(n), x(n);
  for (double& v : e) v = normal(rng);
  for (int k = 0; k < n; ++k) {  // D x = C e, direct recursion
    double s = 0;
    for (int i = 0; i < c.size(); ++i)
      if (k - i >= 0) s += c(i) * e[k - i];
    for (int i = 1; i < d.size(); ++i)
      if (k - i >= 0) s -= d(i) * x[k - i];
    x[k] = s;
  }
  return x;
}

TEST(FilterDt, MatchesDirectRecursion) {
  Eigen::VectorXd b(3), a(2);
  b << 1, -0.4, 0.2;
  a << 1, -0.7;
  const std::vector<double> x = binary_input(50, 3, 7);
  Eigen::VectorXd y(50);
  bj_detail::filter_dt<double>(b, a, x.data(), 50, y.data());
  for (int k = 0; k < 50; ++k) {
    double s = b(0) * x[k];
    if (k >= 1) s += b(1) * x[k - 1] - a(1) * y(k - 1);
    if (k >= 2) s += b(2) * x[k - 2];
    EXPECT_NEAR(y(k), s, 1e-14) << "k = " << k;
  }
}

TEST(ArmaEstimate, KnownArma11WithinReportedErrors) {
  Eigen::VectorXd c(2), d(2);
  c << 1, 0.5;
  d << 1, -0.8;
  const int n = 20000;
  const std::vector<double> x = arma_process(c, d, n, 0.3, 11);
  ArmaResult<double> r;
  ASSERT_TRUE(arma_estimate<double>(x.data(), n, 1, 1, {}, &r).ok());
  EXPECT_TRUE(r.converged);
  const double sd_d = std::sqrt(r.covariance(0, 0));
  const double sd_c = std::sqrt(r.covariance(1, 1));
  EXPECT_NEAR(r.d(1), -0.8, 4 * sd_d) << "sd " << sd_d;
  EXPECT_NEAR(r.c(1), 0.5, 4 * sd_c) << "sd " << sd_c;
  // Asymptotic ARMA(1,1) variances (Box-Jenkins): var(d) = (1-d^2)(1+cd)^2
  // / ((c+d)^2 N) with d the AR coefficient 0.8 and c = 0.5.
  const double phi = 0.8, th = 0.5;
  const double v_ar =
      (1 - phi * phi) * std::pow(1 + phi * th, 2) / std::pow(phi + th, 2) / n;
  EXPECT_NEAR(sd_d / std::sqrt(v_ar), 1.0, 0.1);
  EXPECT_NEAR(r.innovation_variance / 0.09, 1.0, 0.05);
}

TEST(ArmaEstimate, Arma22) {
  Eigen::VectorXd c(3), d(3);
  c << 1, -0.3, 0.2;
  d << 1, -1.2, 0.5;
  const int n = 30000;
  const std::vector<double> x = arma_process(c, d, n, 1.0, 5);
  ArmaResult<double> r;
  ASSERT_TRUE(arma_estimate<double>(x.data(), n, 2, 2, {}, &r).ok());
  for (int i = 1; i <= 2; ++i) {
    EXPECT_NEAR(r.d(i), d(i), 4 * std::sqrt(r.covariance(i - 1, i - 1)));
    EXPECT_NEAR(r.c(i), c(i), 4 * std::sqrt(r.covariance(i + 1, i + 1)));
  }
}

TEST(ArmaEstimate, PureArIsLeastSquares) {
  Eigen::VectorXd c(1), d(3);
  c << 1;
  d << 1, -1.5, 0.7;
  const int n = 2000;
  const std::vector<double> x = arma_process(c, d, n, 1.0, 3);
  ArmaResult<double> r;
  ASSERT_TRUE(arma_estimate<double>(x.data(), n, 2, 0, {}, &r).ok());
  // Normal equations of x(t) = -d1 x(t-1) - d2 x(t-2) + e(t), t >= 2.
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  for (int t = 2; t < n; ++t) {
    const Eigen::Vector2d phi(-x[t - 1], -x[t - 2]);
    M += phi * phi.transpose();
    v += phi * x[t];
  }
  const Eigen::Vector2d ls = M.ldlt().solve(v);
  EXPECT_NEAR(r.d(1), ls(0), 1e-10);
  EXPECT_NEAR(r.d(2), ls(1), 1e-10);
}

// IVARMA's fixed point solves the prediction-error score equation: it is
// the PEM estimate (up to the two iterations' tolerances), with the same
// covariance sigma_e^2 (sum psi psi^T)^-1.
TEST(Ivarma, FixedPointIsThePemEstimate) {
  Eigen::VectorXd c(3), d(3);
  c << 1, -0.3, 0.2;
  d << 1, -1.2, 0.5;
  const int n = 10000;
  const std::vector<double> x = arma_process(c, d, n, 1.0, 31);
  ArmaSettings<double> pem;
  pem.tolerance = 1e-14;
  pem.max_iterations = 200;
  ArmaSettings<double> iv = pem;
  iv.method = ArmaMethod::kIvarma;
  iv.tolerance = 1e-12;
  ArmaResult<double> rp, ri;
  ASSERT_TRUE(arma_estimate<double>(x.data(), n, 2, 2, pem, &rp).ok());
  ASSERT_TRUE(arma_estimate<double>(x.data(), n, 2, 2, iv, &ri).ok());
  EXPECT_TRUE(ri.converged) << ri.iterations;
  for (int i = 1; i <= 2; ++i) {
    EXPECT_NEAR(ri.d(i), rp.d(i), 1e-6);
    EXPECT_NEAR(ri.c(i), rp.c(i), 1e-6);
  }
  EXPECT_NEAR(ri.innovation_variance / rp.innovation_variance, 1.0, 1e-10);
  EXPECT_LT((ri.covariance - rp.covariance).norm(),
            1e-4 * rp.covariance.norm());
}

// IVARMA's spread over independent ARMA(1,1) records against its reported
// standard deviations and the Box-Jenkins asymptotic value.
TEST(Ivarma, MonteCarloSpreadMatchesReportedSd) {
  Eigen::VectorXd c(2), d(2);
  c << 1, 0.5;
  d << 1, -0.8;
  const int n = 2000, runs = 200;
  ArmaSettings<double> iv;
  iv.method = ArmaMethod::kIvarma;
  std::vector<double> dd, cc;
  double sd_d = 0, sd_c = 0;
  for (int k = 0; k < runs; ++k) {
    const std::vector<double> x = arma_process(c, d, n, 1.0, 1000 + k);
    ArmaResult<double> r;
    ASSERT_TRUE(arma_estimate<double>(x.data(), n, 1, 1, iv, &r).ok());
    dd.push_back(r.d(1));
    cc.push_back(r.c(1));
    sd_d += std::sqrt(r.covariance(0, 0)) / runs;
    sd_c += std::sqrt(r.covariance(1, 1)) / runs;
  }
  auto spread = [](const std::vector<double>& v) {
    double m = 0, s = 0;
    for (double a : v) m += a / v.size();
    for (double a : v) s += (a - m) * (a - m) / (v.size() - 1);
    return std::sqrt(s);
  };
  // 200 runs: the sample sd's relative sd is 5 %; bar 0.8-1.25.
  EXPECT_GT(spread(dd) / sd_d, 0.8) << spread(dd) << " " << sd_d;
  EXPECT_LT(spread(dd) / sd_d, 1.25) << spread(dd) << " " << sd_d;
  EXPECT_GT(spread(cc) / sd_c, 0.8) << spread(cc) << " " << sd_c;
  EXPECT_LT(spread(cc) / sd_c, 1.25) << spread(cc) << " " << sd_c;
  const double phi = 0.8, th = 0.5;
  const double v_ar =
      (1 - phi * phi) * std::pow(1 + phi * th, 2) / std::pow(phi + th, 2) / n;
  EXPECT_NEAR(sd_d / std::sqrt(v_ar), 1.0, 0.1);
}

TEST(ArmaEstimate, BadInput) {
  std::vector<double> x(100, 1.0);
  ArmaResult<double> r;
  EXPECT_EQ(arma_estimate<double>(x.data(), 100, -1, 0, {}, &r).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(arma_estimate<double>(x.data(), 20, 2, 2, {}, &r).code(),
            ErrorCode::kBadInput);
}

struct Plant {
  Eigen::VectorXd b, f;  // f = [1 f1 .. fn]
};

Plant second_order() {
  Plant p;
  p.b.resize(2);
  p.b << 1.5, 4;
  p.f.resize(3);
  p.f << 1, 1.2, 4;
  return p;
}

Eigen::VectorXd truth(const Plant& p) {
  Eigen::VectorXd t(p.f.size() - 1 + p.b.size());
  t << p.f.tail(p.f.size() - 1), p.b;
  return t;
}

TEST(Rivc, NoiseFreeExactOpenLoop) {
  const Plant p = second_order();
  const double ts = 0.05;
  const int n = 3000;
  const std::vector<double> u = binary_input(n, 10, 21);
  const std::vector<double> y = simulate_zoh(p.b, p.f, u, ts);
  RivcProblem<double> problem;
  problem.nb = 2;
  problem.nf = 2;
  problem.nc = 1;
  problem.nd = 2;
  RivcSettings<double> settings;
  settings.tolerance = 1e-10;
  RivcData<double> data{y.data(), u.data(), n, ts};
  RivcResult<double> r;
  const Status s = rivc<double>(problem, settings, data, &r);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_LT(relative_error(r.theta, truth(p)), 1e-8) << r.theta.transpose();
}

// MISO RIVC: two inputs, one denominator each, exact from noise-free data;
// the covariance holds the cross-input blocks (stacked instruments).
TEST(RivcMiso, NoiseFreeExactTwoInputs) {
  const Plant p = second_order();
  Eigen::VectorXd b2(1), f2(2);
  b2 << 2;
  f2 << 1, 0.5;
  const double ts = 0.05;
  const int n = 3000, nk2 = 2;
  const std::vector<double> u1 = binary_input(n, 10, 41);
  const std::vector<double> u2 = binary_input(n, 15, 42);
  std::vector<double> u2d(n, 0.0);
  for (int k = nk2; k < n; ++k) u2d[k] = u2[k - nk2];
  const std::vector<double> x1 = simulate_zoh(p.b, p.f, u1, ts);
  const std::vector<double> x2 = simulate_zoh(b2, f2, u2d, ts);
  std::vector<double> y(n), u(2 * n);
  for (int k = 0; k < n; ++k) {
    y[k] = x1[k] + x2[k];
    u[k] = u1[k];
    u[n + k] = u2[k];
  }
  RivcMisoProblem<double> problem;
  problem.inputs = {{2, 2, 0}, {1, 1, nk2}};
  problem.nc = 1;
  problem.nd = 1;
  RivcSettings<double> settings;
  settings.tolerance = 1e-10;
  RivcMisoData<double> data{y.data(), u.data(), n, ts};
  RivcResult<double> r;
  const Status s = rivc_miso<double>(problem, settings, data, &r);
  ASSERT_TRUE(s.ok()) << s.message();
  Eigen::VectorXd want(6);
  want << 1.2, 4, 0.5, 1.5, 4, 2;  // [f_1 f_2 b_1 b_2]
  EXPECT_LT(relative_error(r.theta, want), 1e-8) << r.theta.transpose();
  EXPECT_EQ(r.covariance.rows(), 6);
  RivcMisoProblem<double> bad = problem;
  bad.inputs[1].nb = 3;
  EXPECT_EQ(rivc_miso<double>(bad, settings, data, &r).code(),
            ErrorCode::kBadInput);
  bad.inputs.clear();
  EXPECT_EQ(rivc_miso<double>(bad, settings, data, &r).code(),
            ErrorCode::kBadInput);
}

TEST(Rivc, NoiseFreeExactWithDelay) {
  const Plant p = second_order();
  const double ts = 0.05;
  const int n = 3000, nk = 3;
  const std::vector<double> u = binary_input(n, 10, 22);
  std::vector<double> ud(n, 0.0);
  for (int k = nk; k < n; ++k) ud[k] = u[k - nk];
  const std::vector<double> y = simulate_zoh(p.b, p.f, ud, ts);
  RivcProblem<double> problem;
  problem.nb = 2;
  problem.nf = 2;
  problem.nc = 1;
  problem.nd = 1;
  problem.nk = nk;
  RivcSettings<double> settings;
  settings.tolerance = 1e-10;
  RivcData<double> data{y.data(), u.data(), n, ts};
  RivcResult<double> r;
  ASSERT_TRUE(rivc<double>(problem, settings, data, &r).ok());
  EXPECT_LT(relative_error(r.theta, truth(p)), 1e-8);
}

TEST(Rivc, WhiteNoiseModelIsSrivcFixedPoint) {
  // nc = nd = 0: the RIVC iteration is SRIVC's, so from the engine's SRIVC
  // estimate it stays there.
  const Plant p = second_order();
  const double ts = 0.05;
  const int n = 4000;
  const std::vector<double> u = binary_input(n, 10, 23);
  std::vector<double> y = simulate_zoh(p.b, p.f, u, ts);
  std::mt19937 rng(4);
  std::normal_distribution<double> normal(0, 0.1);
  for (double& v : y) v += normal(rng);
  RivcProblem<double> problem;
  problem.nb = 2;
  problem.nf = 2;
  RivcSettings<double> settings;
  settings.tolerance = 1e-10;
  settings.start.tolerance = 1e-12;
  settings.start.max_iterations = 200;
  RivcData<double> data{y.data(), u.data(), n, ts};
  RivcResult<double> r;
  ASSERT_TRUE(rivc<double>(problem, settings, data, &r).ok());
  EXPECT_LT(relative_error(r.theta, r.start_theta), 1e-6);
  EXPECT_LE(r.iterations, 3);
}

TEST(Rivc, BadInput) {
  const Plant p = second_order();
  const int n = 3000;
  const std::vector<double> u = binary_input(n, 10, 21);
  const std::vector<double> y = simulate_zoh(p.b, p.f, u, 0.05);
  RivcData<double> data{y.data(), u.data(), n, 0.05};
  RivcSettings<double> settings;
  RivcResult<double> r;
  RivcProblem<double> problem;
  problem.nf = 2;
  problem.nb = 4;  // improper
  EXPECT_EQ(rivc<double>(problem, settings, data, &r).code(),
            ErrorCode::kBadInput);
  problem.nb = 2;
  problem.nk = n;  // delay out of range
  EXPECT_EQ(rivc<double>(problem, settings, data, &r).code(),
            ErrorCode::kBadInput);
  problem.nk = 0;
  const std::vector<double> zero(n, 0.0);  // no excitation
  RivcData<double> flat{y.data(), zero.data(), n, 0.05};
  EXPECT_NE(rivc<double>(problem, settings, flat, &r).code(), ErrorCode::kOk);
  settings.max_iterations = 0;
  EXPECT_EQ(rivc<double>(problem, settings, data, &r).code(),
            ErrorCode::kBadOption);
}

// Closed loop u = C(p) (r - y), C = (0.5 p + 1) / (0.1 p^2 + p), plant
// 3 / (p^2 + 2p + 3): y = G C / (1 + G C) r, u = C / (1 + G C) r, Ts =
// 0.01 s, 6000 samples of a binary r held over 100 samples (the record of
// both closed-loop tests). The controller is strictly proper so that u is
// continuous: the regressors use the measured u, filtered as linear
// between samples (FOH), exact to O((w Ts)^2) for a continuous u (a jump
// of u between samples, from a biproper controller and a step in r, would
// be an O(Ts) error).
struct ClosedLoopRecord {
  static constexpr double ts = 0.01;
  static constexpr int n = 6000;
  Eigen::VectorXd nc, dc, b, f, acl, fnc;
  std::vector<double> r, y, u;

  explicit ClosedLoopRecord(unsigned seed) : nc(2), dc(3), b(1), f(3) {
    r = binary_input(n, 100, seed);
    nc << 0.5, 1;
    dc << 0.1, 1, 0;
    b << 3;
    f << 1, 2, 3;
    const Eigen::VectorXd bnc = convolve<double>(b, nc);
    acl = convolve<double>(f, dc);
    acl.tail(bnc.size()) += bnc;
    fnc = convolve<double>(f, nc);
    y = simulate_zoh(bnc, acl, r, ts);
    u = simulate_zoh(fnc, acl, r, ts);
  }
  Eigen::VectorXd plant_theta() const {
    Eigen::VectorXd t(3);
    t << f(1), f(2), b(0);
    return t;
  }
};

TEST(Clrivc, NoiseFreeExact) {
  const ClosedLoopRecord rec(31);
  RivcProblem<double> problem;
  problem.nb = 1;
  problem.nf = 2;
  problem.nc = 1;
  problem.nd = 1;
  problem.u_rule = InterSample::kFoh;
  problem.controller_num = rec.nc;
  problem.controller_den = rec.dc;
  problem.reference = rec.r.data();
  RivcSettings<double> settings;
  settings.tolerance = 1e-10;
  RivcData<double> data{rec.y.data(), rec.u.data(), rec.n, rec.ts};
  RivcResult<double> res;
  const Status s = rivc<double>(problem, settings, data, &res);
  ASSERT_TRUE(s.ok()) << s.message();
  // u is continuous, not piecewise linear: FOH filtering of u is exact
  // only to O((w Ts)^2) (Ts = 0.01 s, loop bandwidth ~10 rad/s: 1e-2 at
  // the fastest, ~1e-4 over the record).
  EXPECT_LT(relative_error(res.theta, rec.plant_theta()), 1e-3)
      << res.theta.transpose();
}

// The same plant and controller in the loop u = r1 - C(p) y (r1 at the
// plant input, CONTSID's closedloop demos): y = G Dc / Acl r1, u = F Dc /
// Acl r1. r1 is a binary signal through W = 10 / (p + 10), so that u = r1
// - C y is continuous (FOH to O((w Ts)^2), as above); the records are W's
// and the loop's responses to the held binary signal, exact at the samples.
struct InputLoopRecord : ClosedLoopRecord {
  std::vector<double> r1;
  explicit InputLoopRecord(unsigned seed) : ClosedLoopRecord(seed) {
    Eigen::VectorXd wn(1), wd(2);
    wn << 10;
    wd << 1, 10;
    const Eigen::VectorXd den = convolve<double>(acl, wd);
    r1 = simulate_zoh(wn, wd, r, ts);
    y = simulate_zoh(convolve<double>(convolve<double>(b, dc), wn), den, r, ts);
    u = simulate_zoh(convolve<double>(convolve<double>(f, dc), wn), den, r, ts);
  }
};

RivcProblem<double> input_loop_problem(const InputLoopRecord& rec,
                                       const std::vector<double>& zero,
                                       bool at_input) {
  RivcProblem<double> problem;
  problem.nb = 1;
  problem.nf = 2;
  problem.u_rule = InterSample::kFoh;
  problem.controller_num = rec.nc;
  problem.controller_den = rec.dc;
  problem.reference = at_input ? zero.data() : rec.r1.data();
  problem.r1 = at_input ? rec.r1.data() : nullptr;
  return problem;
}

TEST(Clrivc, NoiseFreeExactReferenceAtPlantInput) {
  const InputLoopRecord rec(34);
  const std::vector<double> zero(rec.n, 0.0);
  RivcProblem<double> problem = input_loop_problem(rec, zero, true);
  problem.nc = 1;
  problem.nd = 1;
  RivcSettings<double> settings;
  settings.tolerance = 1e-10;
  RivcData<double> data{rec.y.data(), rec.u.data(), rec.n, rec.ts};
  RivcResult<double> res;
  const Status s = rivc<double>(problem, settings, data, &res);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_LT(relative_error(res.theta, rec.plant_theta()), 1e-3)
      << res.theta.transpose();
}

// The IV sandwich (Z^T Phi)^-1 Z^T Z (Phi^T Z)^-1 equals (Z^T Z)^-1 when
// the instruments are the regressors (Z = Phi): to round-off for any Z.
TEST(IvCovariance, SandwichIsInverseGramForZEqualPhi) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0, 1);
  Eigen::MatrixXd Z(500, 4);
  for (Eigen::Index i = 0; i < Z.size(); ++i) Z.data()[i] = normal(rng);
  Z.col(2) *= 1e3;  // badly scaled columns: the equilibration is exercised
  Z.col(3) = 0.9 * Z.col(0) + 0.1 * Z.col(3);
  Eigen::VectorXd target = Z * Eigen::Vector4d(1, -2, 3e-3, 4);
  offline_iv_detail::IvSolution<double> sol;
  double condition = 0;
  ASSERT_TRUE(
      riv_detail::solve_equilibrated<double>(Z, Z, target, "Z", sol, condition)
          .ok());
  const Eigen::MatrixXd gram_inverse = (Z.transpose() * Z).inverse();
  EXPECT_LT((sol.sandwich - gram_inverse).norm(), 1e-9 * gram_inverse.norm());
  EXPECT_LT((sol.inverse_gram - gram_inverse).norm(),
            1e-9 * gram_inverse.norm());
}

// CLRIVC's covariance matrix at the true plant on the noise-free record
// of the loop u = r1 - C y: with r1 given at the plant input the
// instruments are the noise-free regressors (up to the O((w Ts)^2) FOH
// error of u), and the sandwich equals (Z^T Z)^-1; with r1 given as the
// setpoint (instruments of the loop u = C (r1 - y), another loop) it does
// not, and (Z^T Z)^-1 is off by far (the 20-39 times too small sd of
// CONTSID's closedloop1 replay): the sandwich is what is reported.
TEST(Clrivc, SandwichEqualsInverseGramOnlyForTheDataLoop) {
  const InputLoopRecord rec(35);
  const std::vector<double> zero(rec.n, 0.0);
  const RivcData<double> data{rec.y.data(), rec.u.data(), rec.n, rec.ts};
  double mismatch[2];
  for (int at_input = 0; at_input < 2; ++at_input) {
    const RivcProblem<double> problem =
        input_loop_problem(rec, zero, at_input == 1);
    bj_detail::BjIteration<double> iteration(problem, data, 1.0);
    Eigen::VectorXd next, x_hat;
    Eigen::MatrixXd sandwich;
    ArmaResult<double> arma;
    double condition = 0;
    ASSERT_TRUE(iteration
                    .step(rec.plant_theta(), ArmaSettings<double>(), false,
                          next, sandwich, arma, x_hat, condition)
                    .ok());
    const Eigen::MatrixXd& Z = iteration.instruments();
    const Eigen::MatrixXd gram_inverse = (Z.transpose() * Z).inverse();
    // the sandwich (returned in closed loop) against an independent one
    const Eigen::MatrixXd M =
        (Z.transpose() * iteration.regressors()).inverse();
    const Eigen::MatrixXd direct = M * Z.transpose() * Z * M.transpose();
    EXPECT_LT((sandwich - direct).norm(), 1e-6 * direct.norm());
    mismatch[at_input] = (sandwich - gram_inverse).norm() / gram_inverse.norm();
  }
  EXPECT_LT(mismatch[1], 1e-2) << "r1 at the plant input (the data's loop)";
  EXPECT_GT(mismatch[0], 10.0) << "r1 as the setpoint (another loop)";
}

// CL2SRIVC's stages on ClosedLoopRecord: the plant [1 2 0] on u_hat (FOH),
// the loop u/r [4 4 0] (exact: F Nc / Acl).
RivProblem<double> cl2srivc_plant() {
  RivProblem<double> plant;
  plant.nf = {2};
  RivChannel c;
  c.nb = 1;
  c.rule = InterSample::kFoh;
  plant.channels.push_back(c);
  return plant;
}

RivProblem<double> cl2srivc_loop() {
  RivProblem<double> loop;
  loop.nf = {4};
  RivChannel cl;
  cl.nb = 4;
  loop.channels.push_back(cl);
  return loop;
}

TEST(Cl2srivc, NoiseFreeExact) {
  const ClosedLoopRecord rec(32);
  const RivProblem<double> plant = cl2srivc_plant();
  const RivProblem<double> loop = cl2srivc_loop();
  RivSettings<double> settings;
  settings.tolerance = 1e-12;
  settings.max_iterations = 100;
  Cl2srivcResult<double> res;
  const Status s =
      cl2srivc<double>(plant, loop, settings, rec.y.data(), rec.u.data(),
                       rec.r.data(), rec.n, rec.ts, &res);
  ASSERT_TRUE(s.ok()) << s.message();
  // Stage 1 recovers u/r = F Nc / Acl exactly (ZOH r).
  Eigen::VectorXd t1(8);
  t1 << rec.acl.tail(4) / rec.acl(0), rec.fnc / rec.acl(0);
  EXPECT_LT(relative_error(res.sensitivity.theta, t1), 1e-7);
  EXPECT_LT(relative_error(res.plant.theta, rec.plant_theta()), 1e-3)
      << res.plant.theta.transpose();
  // The two-stage covariance exists, is symmetric and positive
  // semi-definite (Bartlett weights); on noise-free data it is at the
  // level of the O((w Ts)^2) model error, far below the plant's scale.
  ASSERT_EQ(res.covariance.rows(), 3);
  EXPECT_LT((res.covariance - res.covariance.transpose()).norm(),
            1e-12 * res.covariance.norm() + 1e-300);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(res.covariance);
  EXPECT_GE(es.eigenvalues().minCoeff(),
            -1e-10 * es.eigenvalues().cwiseAbs().maxCoeff());
  EXPECT_LT(std::sqrt(res.covariance.diagonal().maxCoeff()), 1e-2);
}

// The same start given to cl2srivc's two stages (theta_init for stage 2,
// loop_theta_init for stage 1) reproduces the automatic start's fixed
// point: the starts only decide where the iterations begin.
TEST(Cl2srivc, GivenStartsReachTheSameEstimate) {
  const ClosedLoopRecord rec(33);
  const RivProblem<double> plant = cl2srivc_plant();
  const RivProblem<double> loop = cl2srivc_loop();
  RivSettings<double> settings;
  settings.tolerance = 1e-12;
  settings.max_iterations = 100;
  Cl2srivcResult<double> automatic, given;
  ASSERT_TRUE(cl2srivc<double>(plant, loop, settings, rec.y.data(),
                               rec.u.data(), rec.r.data(), rec.n, rec.ts,
                               &automatic)
                  .ok());
  settings.theta_init = 1.05 * automatic.plant.theta;
  ASSERT_TRUE(
      cl2srivc<double>(plant, loop, settings, rec.y.data(), rec.u.data(),
                       rec.r.data(), rec.n, rec.ts, &given,
                       Eigen::VectorXd(1.05 * automatic.sensitivity.theta))
          .ok());
  EXPECT_LT(
      relative_error(given.sensitivity.theta, automatic.sensitivity.theta),
      1e-9);
  EXPECT_LT(relative_error(given.plant.theta, automatic.plant.theta), 1e-9);
}

}  // namespace
}  // namespace ctid
