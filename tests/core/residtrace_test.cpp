// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/ (track.hpp, responses.hpp):
//   - the tracking recursion against a direct transcription of the
//     update with the random walk after the correction (P = P - K phi^T P
//     + Qn, the stability test by the roots), and, with Qn = 0 and
//     zeta = phi, against the batch least-squares solution it must equal;
//   - a rejected update keeps the previous estimate;
//   - the filtered derivatives against the exact ZOH response computed by
//     the matrix exponential (test_util.hpp) and the exact FOH response by
//     partial fractions;
//   - the free responses against their closed forms, and the zero rows of
//     an unstable or non-finite F;
//   - the zero-lag velocity of a sine against its steady state, the
//     derivative times lambda^2/(lambda^2 + w^2) without phase shift (and
//     the sine itself so scaled), away from the ends' transients;
//   - the Newey-West long-run variance against the known one of an AR(1)
//     series, the Diebold-Mariano and encompassing tests on errors of
//     known relative size and on equal errors, the AR whitener against
//     the coefficients that generated the series, and the whiteness and
//     independence statistics on white, coloured and dependent residuals.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/apps/residtrace/track.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

bool stable_by_roots(const Eigen::VectorXd& a) {
  const Eigen::Index n = a.size();
  if (n == 0) return true;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) c(i + 1, i) = 1;
  for (Eigen::Index i = 0; i < n; ++i) c(0, i) = -a(i);
  return Eigen::EigenSolver<Eigen::MatrixXd>(c, false)
             .eigenvalues()
             .real()
             .maxCoeff() < 0;
}

struct Regression {
  Eigen::VectorXd target;
  Eigen::MatrixXd Phi, Z;
};

// A second-order model y'' + f1 y' + f2 y = b u with f1 drifting: phi =
// [-y', -y, u], zeta = phi plus independent noise (a stand-in for
// instruments), target y'' plus noise.
Regression make_regression(int N, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  Regression r;
  r.target.resize(N);
  r.Phi.resize(N, 3);
  r.Z.resize(N, 3);
  for (int k = 0; k < N; ++k) {
    const double f1 = 1.2 + 0.6 * k / N;
    const double f2 = 4.0;
    const double b = 2.0;
    const Eigen::Vector3d phi(-g(rng), -g(rng), g(rng));
    r.Phi.row(k) = phi.transpose();
    r.Z.row(k) =
        (phi + 0.3 * Eigen::Vector3d(g(rng), g(rng), g(rng))).transpose();
    r.target(k) = phi.dot(Eigen::Vector3d(f1, f2, b)) + noise * g(rng);
  }
  return r;
}

// The recursion as residtrace states it: K = P zeta / (1 + phi' P zeta),
// theta += K e unless F leaves the left half-plane, P += Qn - K phi' P.
void direct_track(const residtrace::TrackConfig<double>& c, const Regression& r,
                  Eigen::MatrixXd* theta, double* V, Eigen::MatrixXd* P_out) {
  const Eigen::Index N = r.Phi.rows();
  const Eigen::Index np = r.Phi.cols();
  Eigen::VectorXd th = c.theta0;
  Eigen::MatrixXd P = c.P0;
  Eigen::VectorXd f = c.f;
  std::vector<double> e2(N, 0), h(N, 1);
  theta->resize(N, np);
  for (Eigen::Index k = 0; k < N; ++k) {
    if (k < c.first) {
      theta->row(k) = c.theta0.transpose();
      continue;
    }
    theta->row(k) = th.transpose();
    const Eigen::VectorXd phi = r.Phi.row(k).transpose();
    const Eigen::VectorXd z = r.Z.row(k).transpose();
    const Eigen::VectorXd Pz = P * z;
    const double den = 1 + phi.dot(Pz);
    const double e = r.target(k) - phi.dot(th);
    const Eigen::VectorXd K = Pz / den;
    const Eigen::VectorXd th_new = th + K * e;
    P += c.Qn - K * (phi.transpose() * P);
    for (std::size_t i = 0; i < c.free.size(); ++i) f(c.free[i]) = th_new(i);
    if (stable_by_roots(f.head(f.size() - c.integrators))) th = th_new;
    e2[k] = e * e;
    h[k] = std::abs(den);
  }
  const Eigen::Index count = N - c.first;
  const Eigen::Index skip = std::min<Eigen::Index>(
      N - 1,
      c.first + std::max<Eigen::Index>(
                    10, static_cast<Eigen::Index>(std::round(count / 50.0))));
  double s = 0, lh = 0;
  for (Eigen::Index k = skip; k < N; ++k) {
    s += e2[k] / h[k];
    lh += std::log(h[k]);
  }
  *V = (N - skip) * std::log(s / (N - skip)) + lh;
  *P_out = P;
}

residtrace::TrackConfig<double> drift_config() {
  residtrace::TrackConfig<double> c;
  c.f = Eigen::Vector2d(1.2, 4.0);
  c.free = {0, 1};
  c.integrators = 0;
  c.theta0 = Eigen::Vector3d(1.2, 4.0, 2.0);
  c.P0 = 0.1 * Eigen::MatrixXd::Identity(3, 3);
  c.Qn = Eigen::Vector3d(1e-4, 1e-6, 1e-6).asDiagonal();
  return c;
}

TEST(ResidtraceTrack, EqualsTheDirectRecursion) {
  const Regression r = make_regression(600, 0.2, 3);
  for (const Eigen::Index first : {0, 37}) {
    residtrace::TrackConfig<double> c = drift_config();
    c.first = first;
    residtrace::TrackResult<double> out;
    ASSERT_TRUE(residtrace::track<double>(c, r.target, r.Phi, r.Z, &out).ok());
    Eigen::MatrixXd theta, P;
    double V = 0;
    direct_track(c, r, &theta, &V, &P);
    EXPECT_TRUE(test::MatrixNear(out.theta, theta, 1e-10));
    EXPECT_TRUE(test::MatrixNear(out.P, P, 1e-10));
    EXPECT_NEAR(out.V, V, 1e-9 * std::abs(V));
    for (Eigen::Index k = 0; k < first; ++k) {
      EXPECT_EQ(out.theta.row(k), c.theta0.transpose());
    }
    // The drift of f1 (1.2 -> 1.8) is followed.
    EXPECT_NEAR(out.theta(599, 0), 1.8, 0.15);
  }
}

TEST(ResidtraceTrack, WithoutRandomWalkIsBatchLeastSquares) {
  Regression r = make_regression(300, 0.1, 5);
  r.Z = r.Phi;
  residtrace::TrackConfig<double> c = drift_config();
  c.Qn.setZero();
  residtrace::TrackResult<double> out;
  ASSERT_TRUE(residtrace::track<double>(c, r.target, r.Phi, r.Z, &out).ok());
  // theta(t_N) of the recursion after N - 1 samples (row N - 1 is the
  // estimate before the last sample): the regularised least squares
  // (P0^-1 + Phi' Phi)^-1 (P0^-1 theta0 + Phi' target) on those samples.
  const Eigen::Index M = r.Phi.rows() - 1;
  const Eigen::MatrixXd A =
      c.P0.inverse() + r.Phi.topRows(M).transpose() * r.Phi.topRows(M);
  const Eigen::VectorXd b = c.P0.inverse() * c.theta0 +
                            r.Phi.topRows(M).transpose() * r.target.head(M);
  const Eigen::VectorXd expected = A.ldlt().solve(b);
  EXPECT_TRUE(test::MatrixNear(out.theta.row(M).transpose(), expected, 1e-9));
}

TEST(ResidtraceTrack, KeepsTheEstimateWhenFWouldBeUnstable) {
  // F = p (p + f1) with the integrator fixed: only f1 is tested. The data
  // pull f1 to -0.5 (unstable); every update that crosses 0 is rejected.
  const int N = 200;
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0, 1);
  Regression r;
  r.target.resize(N);
  r.Phi.resize(N, 2);
  for (int k = 0; k < N; ++k) {
    r.Phi.row(k) = Eigen::RowVector2d(-g(rng), g(rng));
    r.target(k) = r.Phi.row(k).dot(Eigen::RowVector2d(-0.5, 1.0));
  }
  r.Z = r.Phi;
  residtrace::TrackConfig<double> c;
  c.f = Eigen::Vector2d(0.3, 0.0);
  c.free = {0};
  c.integrators = 1;
  c.theta0 = Eigen::Vector2d(0.3, 1.0);
  c.P0 = Eigen::MatrixXd::Identity(2, 2);
  c.Qn = 1e-3 * Eigen::MatrixXd::Identity(2, 2);
  residtrace::TrackResult<double> out;
  ASSERT_TRUE(residtrace::track<double>(c, r.target, r.Phi, r.Z, &out).ok());
  EXPECT_GT(out.theta.col(0).minCoeff(), 0.0);
  Eigen::MatrixXd theta, P;
  double V = 0;
  direct_track(c, r, &theta, &V, &P);
  EXPECT_TRUE(test::MatrixNear(out.theta, theta, 1e-10));
  // Some update was rejected: the estimate stays the same across a sample.
  int kept = 0;
  for (int k = 1; k < N; ++k) kept += out.theta(k, 0) == out.theta(k - 1, 0);
  EXPECT_GT(kept, 0);
}

TEST(ResidtraceTrack, RejectsBadSizes) {
  const Regression r = make_regression(50, 0.1, 1);
  residtrace::TrackConfig<double> c = drift_config();
  residtrace::TrackResult<double> out;
  c.free = {0, 2};
  EXPECT_EQ(residtrace::track<double>(c, r.target, r.Phi, r.Z, &out).code(),
            ErrorCode::kBadInput);
  c = drift_config();
  c.P0 = Eigen::MatrixXd::Identity(2, 2);
  EXPECT_EQ(residtrace::track<double>(c, r.target, r.Phi, r.Z, &out).code(),
            ErrorCode::kDimensionMismatch);
  c = drift_config();
  c.first = 51;
  EXPECT_EQ(residtrace::track<double>(c, r.target, r.Phi, r.Z, &out).code(),
            ErrorCode::kBadInput);
}

std::vector<double> test_signal(int N, double ts) {
  std::mt19937 rng(2);
  std::normal_distribution<double> noise(0, 0.2);
  std::vector<double> s(N);
  for (int k = 0; k < N; ++k) {
    s[k] = std::sin(0.9 * k * ts) + std::cos(3.1 * k * ts) + noise(rng);
  }
  return s;
}

TEST(ResidtraceResponses, ZohDerivativesMatchTheMatrixExponential) {
  const double ts = 0.05;
  const int N = 400;
  const std::vector<double> x = test_signal(N, ts);
  const Eigen::Vector3d f(3.5, 6.0, 4.0);  // a real root and a pair
  Eigen::MatrixXd D;
  ASSERT_TRUE(residtrace::filtered_derivatives<double>(f, ts, InterSample::kZoh,
                                                       x.data(), N, D)
                  .ok());
  ASSERT_EQ(D.cols(), 4);
  const Eigen::Vector4d den(1, f(0), f(1), f(2));
  for (int i = 0; i < 3; ++i) {  // p^i / F, strictly proper
    Eigen::VectorXd num = Eigen::VectorXd::Zero(i + 1);
    num(0) = 1;
    const std::vector<double> y = test::simulate_zoh(num, den, x, ts);
    const Eigen::Map<const Eigen::VectorXd> expected(y.data(), N);
    EXPECT_LT(test::relative_error(D.col(i), expected), 1e-10) << "i " << i;
  }
  // p^n / F = 1 - (f1 p^2 + f2 p + f3) / F.
  Eigen::VectorXd highest = Eigen::Map<const Eigen::VectorXd>(x.data(), N);
  for (int i = 0; i < 3; ++i) highest -= f(2 - i) * D.col(i);
  EXPECT_LT(test::relative_error(D.col(3), highest), 1e-12);
}

// The exact FOH response of 1/(p - r), x linear between samples, at rest
// at the first sample: m_k = a m_(k-1) + g0 x_(k-1) + g1 x_k.
std::vector<std::complex<double>> foh_mode(std::complex<double> r,
                                           const std::vector<double>& x,
                                           double ts) {
  const std::complex<double> z = r * ts;
  const std::complex<double> a = std::exp(z);
  const std::complex<double> phi1 = (a - 1.0) / z;
  const std::complex<double> phi2 = (a - 1.0 - z) / (z * z);
  const std::complex<double> g1 = ts * phi2;
  const std::complex<double> g0 = ts * phi1 - g1;
  std::vector<std::complex<double>> m(x.size(), 0.0);
  for (std::size_t k = 1; k < x.size(); ++k) {
    m[k] = a * m[k - 1] + g0 * x[k - 1] + g1 * x[k];
  }
  return m;
}

TEST(ResidtraceResponses, FohDerivativesMatchPartialFractions) {
  const double ts = 0.05;
  const int N = 400;
  const std::vector<double> x = test_signal(N, ts);
  // F = (p + 1)(p + 2)(p + 4): p^i / F = sum_k r_k^i / F'(r_k) / (p - r_k)
  // for i < 3.
  const double roots[3] = {-1, -2, -4};
  const Eigen::Vector3d f(7, 14, 8);
  Eigen::MatrixXd D;
  ASSERT_TRUE(residtrace::filtered_derivatives<double>(f, ts, InterSample::kFoh,
                                                       x.data(), N, D)
                  .ok());
  for (int i = 0; i < 3; ++i) {
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(N);
    for (int k = 0; k < 3; ++k) {
      double dF = 1;
      for (int j = 0; j < 3; ++j) {
        if (j != k) dF *= roots[k] - roots[j];
      }
      const auto m = foh_mode(roots[k], x, ts);
      for (int t = 0; t < N; ++t) {
        expected(t) += std::pow(roots[k], i) / dF * m[t].real();
      }
    }
    EXPECT_LT(test::relative_error(D.col(i), expected), 1e-10) << "i " << i;
  }
}

TEST(ResidtraceResponses, FreeResponsesMatchTheClosedForm) {
  // F = (p + a)(p + b): h(0) = 1, h'(0) = 0 gives (b e^-at - a e^-bt) /
  // (b - a); h(0) = 0, h'(0) = 1 gives (e^-at - e^-bt) / (b - a).
  const double a = 0.7, b = 3.0, ts = 0.1;
  const int N = 200;
  Eigen::MatrixXd X;
  ASSERT_TRUE(residtrace::free_responses<double>(Eigen::Vector2d(a + b, a * b),
                                                 ts, N, X)
                  .ok());
  ASSERT_EQ(X.rows(), N);
  ASSERT_EQ(X.cols(), 2);
  for (int k = 0; k < N; ++k) {
    const double t = k * ts;
    EXPECT_NEAR(X(k, 0),
                (b * std::exp(-a * t) - a * std::exp(-b * t)) / (b - a), 1e-12);
    EXPECT_NEAR(X(k, 1), (std::exp(-a * t) - std::exp(-b * t)) / (b - a),
                1e-12);
  }
}

TEST(ResidtraceResponses, UnstableOrNonFiniteFGivesZeroRows) {
  Eigen::MatrixXd X;
  // p - 50: e^(50 t) overflows after about 142 samples of 0.1 s.
  ASSERT_TRUE(residtrace::free_responses<double>(
                  Eigen::VectorXd::Constant(1, -50.0), 0.1, 400, X)
                  .ok());
  EXPECT_TRUE(X.allFinite());
  EXPECT_GT(X(100, 0), 1e200);
  EXPECT_EQ(X(399, 0), 0.0);
  ASSERT_TRUE(residtrace::free_responses<double>(
                  Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 1),
                  0.1, 5, X)
                  .ok());
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(5, 2);
  expected(0, 0) = 1;
  EXPECT_EQ(X, expected);
  EXPECT_EQ(residtrace::free_responses<double>(Eigen::Vector2d(1, 1), 0.0, 5, X)
                .code(),
            ErrorCode::kBadInput);
}

std::vector<double> white(int N, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<double> v(N);
  for (double& x : v) x = g(rng);
  return v;
}

Eigen::VectorXd as_vector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
}

// g_t = phi g_(t-1) + eps_t, var(eps) = 1: long-run variance 1/(1-phi)^2.
TEST(ResidtraceResponses, ZeroLagVelocityOfASineIsInPhase) {
  const double ts = 1e-3, w = 2, lambda = 30;
  const Eigen::Index N = 6001;
  Eigen::VectorXd y(N);
  for (Eigen::Index k = 0; k < N; ++k) y(k) = std::sin(w * ts * k);
  const double g = lambda * lambda / (lambda * lambda + w * w);
  Eigen::VectorXd v, s;
  ASSERT_TRUE(
      residtrace::zero_lag_velocity<double>(y.data(), N, ts, lambda, false, &v)
          .ok());
  ASSERT_TRUE(
      residtrace::zero_lag_velocity<double>(y.data(), N, ts, lambda, true, &s)
          .ok());
  ASSERT_EQ(v.size(), N);
  // the transients exp(-lambda t) of both ends have decayed after 1 s
  for (Eigen::Index k = 1000; k < N - 1000; ++k) {
    EXPECT_NEAR(v(k), g * w * std::cos(w * ts * k), 1e-5);
    EXPECT_NEAR(s(k), g * std::sin(w * ts * k), 1e-5);
  }
  EXPECT_FALSE(
      residtrace::zero_lag_velocity<double>(y.data(), N, ts, -1.0, false, &v)
          .ok());
}

TEST(ResidtraceStatistics, NeweyWestMatchesTheAr1LongRunVariance) {
  const int N = 40000;
  const std::vector<double> eps = white(N, 21);
  for (const double phi : {0.0, 0.5, -0.4}) {
    Eigen::VectorXd g(N);
    g(0) = eps[0];
    for (int k = 1; k < N; ++k) g(k) = phi * g(k - 1) + eps[k];
    const residtrace::LongRunVariance<double> nw = residtrace::newey_west(g);
    const double expected = 1 / ((1 - phi) * (1 - phi));
    EXPECT_NEAR(nw.variance, expected, 0.08 * expected) << "phi " << phi;
    // The prewhitened series is white: a short window.
    EXPECT_LE(nw.bandwidth, 3) << "phi " << phi;
  }
  // A constant has no variance.
  EXPECT_EQ(residtrace::newey_west<double>(Eigen::VectorXd::Constant(50, 2.0))
                .variance,
            0.0);
}

TEST(ResidtraceStatistics, DieboldMarianoOnKnownErrors) {
  const int N = 2000;
  const Eigen::VectorXd e0 = as_vector(white(N, 31));
  const Eigen::VectorXd noise = as_vector(white(N, 32));
  // e1 = e0 / 2: a quarter of the mean square, clearly better; the
  // correction e0 - e1 explains e0 exactly, so the encompassing score has
  // no variance and z is 0 by definition.
  residtrace::DmTest<double> t;
  ASSERT_TRUE(residtrace::dm_test<double>(e0, e0 / 2, &t).ok());
  EXPECT_NEAR(t.score, 0.75, 1e-12);
  EXPECT_GT(t.stat, 10);
  EXPECT_LT(t.p, 1e-10);
  EXPECT_EQ(t.z, 0.0);
  // e1 = e0 / 2 + 0.3 noise: 0.34 of the mean square in expectation, and
  // the correction explains part of e0.
  ASSERT_TRUE(residtrace::dm_test<double>(e0, e0 / 2 + 0.3 * noise, &t).ok());
  EXPECT_NEAR(t.score, 0.66, 0.05);
  EXPECT_GT(t.stat, 10);
  EXPECT_GT(t.z, 10);
  EXPECT_LT(t.p_corr, 1e-10);
  // Equal errors: no difference, nothing to test.
  ASSERT_TRUE(residtrace::dm_test<double>(e0, e0, &t).ok());
  EXPECT_EQ(t.score, 0.0);
  EXPECT_EQ(t.stat, 0.0);
  EXPECT_EQ(t.p, 1.0);
  EXPECT_EQ(t.z, 0.0);
  EXPECT_EQ(t.p_corr, 0.5);
  // Two independent errors of the same size: no significant difference.
  ASSERT_TRUE(residtrace::dm_test<double>(e0, noise, &t).ok());
  EXPECT_GT(t.p, 0.001);
  EXPECT_LT(t.p, 0.999);
  EXPECT_NEAR(t.p, 0.5 * std::erfc(t.stat / std::sqrt(2.0)), 1e-15);
  EXPECT_EQ(residtrace::dm_test<double>(e0, noise.head(10), &t).code(),
            ErrorCode::kDimensionMismatch);
}

TEST(ResidtraceStatistics, ArWhitenerFindsTheGeneratingModel) {
  // x_t = 1.2 x_(t-1) - 0.5 x_(t-2) + eps_t: A(q) = [1 -1.2 0.5].
  const int N = 8000;
  const std::vector<double> eps = white(N, 41);
  Eigen::VectorXd x(N);
  x(0) = eps[0];
  x(1) = 1.2 * x(0) + eps[1];
  for (int k = 2; k < N; ++k) x(k) = 1.2 * x(k - 1) - 0.5 * x(k - 2) + eps[k];
  const Eigen::VectorXd a = residtrace::ar_whitener(x, 10);
  ASSERT_EQ(a.size(), 3);
  EXPECT_TRUE(test::MatrixNear(a, Eigen::Vector3d(1, -1.2, 0.5), 0.03));
  // The filter A(q) returns the innovations (after the first two samples).
  const Eigen::VectorXd w =
      residtrace::fir<double>(Eigen::Vector3d(1, -1.2, 0.5), x);
  for (int k = 2; k < N; ++k) EXPECT_NEAR(w(k), eps[k], 1e-12);
}

TEST(ResidtraceStatistics, WhitenessAndIndependence) {
  const int N = 3000, m = 20;
  const Eigen::VectorXd e = as_vector(white(N, 51));
  const Eigen::VectorXd u = as_vector(white(N, 52));
  residtrace::WhitenessStatistics<double> w;
  ASSERT_TRUE(residtrace::whiteness_statistics<double>(e, u, m, 1.0, &w).ok());
  ASSERT_TRUE(w.testable);
  EXPECT_NEAR(w.autocorr(0), 1.0, 1e-15);
  // Ljung-Box from the sample autocorrelations, computed here.
  const Eigen::VectorXd ec = e.array() - e.mean();
  double q = 0;
  for (int k = 1; k <= m; ++k) {
    const double rk = ec.tail(N - k).dot(ec.head(N - k)) / ec.squaredNorm();
    q += rk * rk / (N - k);
  }
  EXPECT_NEAR(w.Q, double(N) * (N + 2) * q, 1e-9 * w.Q);
  // chi^2 quantiles at 0.999: 45.3 (20 dof), 80.1 (41 dof).
  EXPECT_LT(w.Q, 45.3);
  EXPECT_LT(w.S_indep, 80.1);
  // A residual that carries the input two samples back, through a
  // coloured path: dependent, the largest correlation at lag 2.
  Eigen::VectorXd d = 0.3 * e;
  for (int k = 2; k < N; ++k) d(k) += u(k - 2) + (k > 2 ? 0.8 * u(k - 3) : 0);
  ASSERT_TRUE(residtrace::whiteness_statistics<double>(d, u, m, 1.0, &w).ok());
  Eigen::Index lag = 0;
  w.xcorr.col(0).cwiseAbs().maxCoeff(&lag);
  EXPECT_EQ(lag - m, 2);
  EXPECT_GT(w.S_indep, 1000);
  EXPECT_GT(w.Q, 45.3);  // and coloured
}

TEST(ResidtraceStatistics, UntestableResiduals) {
  residtrace::WhitenessStatistics<double> w;
  const Eigen::MatrixXd u = Eigen::MatrixXd::Ones(40, 1);
  Eigen::VectorXd e = Eigen::VectorXd::Constant(40, 0.5);
  ASSERT_TRUE(residtrace::whiteness_statistics<double>(e, u, 5, 1.0, &w).ok());
  EXPECT_FALSE(w.testable);
  EXPECT_NE(w.reason.find("constant"), std::string::npos);
  e.setConstant(1e-12);
  ASSERT_TRUE(residtrace::whiteness_statistics<double>(e, u, 5, 1.0, &w).ok());
  EXPECT_NE(w.reason.find("rounding"), std::string::npos);
  e(3) = std::numeric_limits<double>::infinity();
  ASSERT_TRUE(residtrace::whiteness_statistics<double>(e, u, 5, 1.0, &w).ok());
  EXPECT_NE(w.reason.find("not finite"), std::string::npos);
  EXPECT_EQ(
      residtrace::whiteness_statistics<double>(e, u.topRows(3), 5, 1.0, &w)
          .code(),
      ErrorCode::kDimensionMismatch);
}

}  // namespace
}  // namespace ctid
