// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/freq_srivc.hpp: SRIVC and the
// frequency-domain output error (the Levenberg-Marquardt of
// output_error.hpp on Y - G U) recover a known transfer function exactly
// from noise-free frequency data, also from a poor start and with a delay;
// on noisy data the output-error optimum is a stationary point of the loss
// evaluated independently here (complex arithmetic, central differences),
// and its loss is not above SRIVC's.
#include "ctid/offline/freq_srivc.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <random>
#include <vector>

namespace ctid {
namespace {

using C = std::complex<double>;

C polyval(const std::vector<double>& c, C s) {
  C v = 0;
  for (double x : c) v = v * s + x;
  return v;
}

// G(jw) = b/f e^(-jw td), f monic descending (with its leading 1).
std::vector<C> response(const std::vector<double>& b,
                        const std::vector<double>& f, double td,
                        const std::vector<double>& w) {
  std::vector<C> g(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) {
    const C s(0, w[k]);
    g[k] = polyval(b, s) / polyval(f, s) * std::exp(C(0, -w[k] * td));
  }
  return g;
}

std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> w(n);
  for (int k = 0; k < n; ++k)
    w[k] = lo * std::pow(hi / lo, static_cast<double>(k) / (n - 1));
  return w;
}

// sum_k |G_k - b/f(jw_k) e^(-jw td)|^2 / K with theta = [f1..fn b..].
double loss(const std::vector<C>& g, const std::vector<double>& w,
            const Eigen::VectorXd& theta, int na, double td) {
  std::vector<double> f(na + 1), b(theta.size() - na);
  f[0] = 1;
  for (int i = 0; i < na; ++i) f[i + 1] = theta(i);
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = theta(na + i);
  const std::vector<C> m = response(b, f, td, w);
  double v = 0;
  for (std::size_t k = 0; k < w.size(); ++k) v += std::norm(g[k] - m[k]);
  return v / static_cast<double>(w.size());
}

FreqData<double> make(const std::vector<double>& w, const std::vector<C>& g) {
  FreqData<double> d;
  d.w = w.data();
  d.y = g.data();
  d.num_frequencies = static_cast<Eigen::Index>(w.size());
  return d;
}

// Two inputs, each with its own denominator and fixed delay: Y = G_1 U_1
// + G_2 U_2 with independent random complex U_1, U_2, noise-free. SRIVC
// (inputs updated in turn) and the output error both recover
// theta = [a_1 a_2 b_1 b_2] exactly.
TEST(FreqSrivc, TwoInputsAreExact) {
  const std::vector<double> b1 = {2, 5}, f1 = {1, 0.8, 4, 2};
  const std::vector<double> b2 = {3}, f2 = {1, 1.5};
  const std::vector<double> w = log_grid(0.1, 20, 80);
  const std::vector<C> g1 = response(b1, f1, 0.2, w);
  const std::vector<C> g2 = response(b2, f2, 0.05, w);
  std::mt19937 gen(4);
  std::normal_distribution<double> normal;
  const std::size_t K = w.size();
  std::vector<C> u(2 * K), y(K);
  for (std::size_t k = 0; k < 2 * K; ++k) u[k] = C(normal(gen), normal(gen));
  for (std::size_t k = 0; k < K; ++k) y[k] = g1[k] * u[k] + g2[k] * u[K + k];
  FreqData<double> d = make(w, y);
  d.u = u.data();
  d.num_inputs = 2;
  for (bool oe : {false, true}) {
    FreqSettings<double> s;
    FreqChannel<double> c1, c2;
    c1.na = 3;
    c1.nb = 2;
    c1.delay = 0.2;
    c2.na = 1;
    c2.nb = 1;
    c2.delay = 0.05;
    s.inputs = {c1, c2};
    s.output_error = oe;
    s.max_iterations = 200;
    FreqResult<double> r;
    ASSERT_TRUE(freq_srivc(s, d, &r).ok()) << r.reason;
    Eigen::VectorXd theta(7);
    theta << r.a, r.b;
    Eigen::VectorXd expect(7);
    expect << 0.8, 4, 2, 1.5, 2, 5, 3;
    EXPECT_LT((theta - expect).norm() / expect.norm(), 1e-8) << oe;
    EXPECT_LT(r.loss, 1e-18);
  }
}

TEST(FreqSrivc, OutputErrorIsExactFromAPoorStart) {
  const std::vector<double> b = {2, 5}, f = {1, 0.8, 4, 2};
  const std::vector<double> w = log_grid(0.1, 20, 80);
  const std::vector<C> g = response(b, f, 0, w);
  FreqSettings<double> s;
  s.na = 3;
  s.nb = 2;
  s.output_error = true;
  s.max_iterations = 200;
  s.theta_init = Eigen::VectorXd(5);
  s.theta_init << 2, 6, 3, 1, 3;  // poles and zeros far from the truth
  FreqResult<double> r;
  ASSERT_TRUE(freq_srivc(s, make(w, g), &r).ok());
  const Eigen::Vector3d a_true(0.8, 4, 2);
  const Eigen::Vector2d b_true(2, 5);
  EXPECT_LT((r.a - a_true).norm() / a_true.norm(), 1e-9) << r.a.transpose();
  EXPECT_LT((r.b - b_true).norm() / b_true.norm(), 1e-9) << r.b.transpose();
  EXPECT_LT(r.loss, 1e-20);
}

TEST(FreqSrivc, OutputErrorEstimatesTheDelayExactly) {
  const std::vector<double> f = {1, 2.4, 4};
  const std::vector<double> w = log_grid(0.1, 10, 60);
  const std::vector<C> g1 = response({4}, f, 0.37, w);
  FreqSettings<double> s;
  s.na = 2;
  s.nb = 1;
  s.output_error = true;
  s.estimate_delay = true;
  s.td_min = 0;
  s.td_max = 1;
  s.num_td = 21;
  FreqResult<double> r;
  ASSERT_TRUE(freq_srivc(s, make(w, g1), &r).ok()) << r.reason;
  EXPECT_NEAR(r.delay, 0.37, 1e-9);
  EXPECT_NEAR(r.a(0), 2.4, 1e-9);
  EXPECT_NEAR(r.a(1), 4, 1e-9);
  EXPECT_NEAR(r.b(0), 4, 1e-9);
  EXPECT_EQ(r.covariance.rows(), 4);
}

TEST(FreqSrivc, NoisyOutputErrorIsAStationaryPointBelowSrivc) {
  const std::vector<double> b = {2, 5}, f = {1, 0.8, 4, 2};
  const std::vector<double> w = log_grid(0.1, 20, 80);
  std::vector<C> g = response(b, f, 0, w);
  std::mt19937 gen(11);
  std::normal_distribution<double> e(0, 0.05);
  for (C& v : g) v += C(e(gen), e(gen));
  FreqSettings<double> s;
  s.na = 3;
  s.nb = 2;
  FreqResult<double> iv, oe;
  ASSERT_TRUE(freq_srivc(s, make(w, g), &iv).ok());
  s.output_error = true;
  ASSERT_TRUE(freq_srivc(s, make(w, g), &oe).ok()) << oe.reason;
  Eigen::VectorXd th(5), th_iv(5);
  th << oe.a, oe.b;
  th_iv << iv.a, iv.b;
  const double v = loss(g, w, th, 3, 0);
  EXPECT_NEAR(v, oe.loss, 1e-12 * v);
  EXPECT_LE(v, loss(g, w, th_iv, 3, 0));
  // the gradient of the independently evaluated loss vanishes (relative
  // to the curvature scale: |dV/dth_i| h_i / V < 1e-6 with h_i = 1e-5
  // |th_i|), and each parameter's perturbation raises it
  for (int i = 0; i < 5; ++i) {
    const double h = 1e-5 * std::abs(th(i));
    Eigen::VectorXd p = th, m = th;
    p(i) += h;
    m(i) -= h;
    const double vp = loss(g, w, p, 3, 0), vm = loss(g, w, m, 3, 0);
    EXPECT_LT(std::abs(vp - vm) / 2 / v, 1e-6) << "parameter " << i;
    EXPECT_GT(vp, v);
    EXPECT_GT(vm, v);
  }
  // covariance: s^2 (J^T J)^-1, positive definite, 5 x 5
  EXPECT_EQ(oe.covariance.rows(), 5);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(oe.covariance);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0);
}

// SRIVC's fixed point in the frequency domain is itself a stationary point
// of the output-error loss (its instruments are the loss's Jacobian), so
// the output-error refinement (TFFCOE) starts at its optimum: the two
// estimates agree, and the independently evaluated loss has a vanishing
// gradient at SRIVC's estimate. With the delay estimated the same holds
// for the concentrated loss's minimum in td.
TEST(FreqSrivc, SrivcFixedPointIsAnOutputErrorStationaryPoint) {
  const std::vector<double> b = {2, 5}, f = {1, 0.8, 4, 2};
  const std::vector<double> w = log_grid(0.1, 20, 80);
  std::vector<C> g = response(b, f, 0.3, w);
  std::mt19937 gen(5);
  std::normal_distribution<double> e(0, 0.05);
  for (C& v : g) v += C(e(gen), e(gen));
  FreqSettings<double> s;
  s.na = 3;
  s.nb = 2;
  s.tolerance = 1e-13;
  s.max_iterations = 500;
  s.estimate_delay = true;
  s.td_min = 0;
  s.td_max = 1;
  s.num_td = 21;
  FreqResult<double> iv, oe;
  ASSERT_TRUE(freq_srivc(s, make(w, g), &iv).ok()) << iv.reason;
  s.output_error = true;
  ASSERT_TRUE(freq_srivc(s, make(w, g), &oe).ok()) << oe.reason;
  Eigen::VectorXd th(6), th_oe(6);
  th << iv.a, iv.b, iv.delay;
  th_oe << oe.a, oe.b, oe.delay;
  EXPECT_LT((th - th_oe).norm() / th.norm(), 1e-8);
  auto v_at = [&](const Eigen::VectorXd& p) {
    return loss(g, w, p.head(5), 3, p(5));
  };
  const double v = v_at(th);
  for (int i = 0; i < 6; ++i) {
    const double h = 1e-5 * std::abs(th(i));
    Eigen::VectorXd p = th, m = th;
    p(i) += h;
    m(i) -= h;
    const double vp = v_at(p), vm = v_at(m);
    EXPECT_LT(std::abs(vp - vm) / 2 / v, 1e-6) << "parameter " << i;
    EXPECT_GT(vp, v);
    EXPECT_GT(vm, v);
  }
}

}  // namespace
}  // namespace ctid
