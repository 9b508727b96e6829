// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The residual statistics of residtrace (octave/residtrace.m):
//
//   dm_test: does the error e1 have a smaller mean square than e0 on the
//     same samples? The Diebold-Mariano test on d = e0^2 - e1^2 (J. Bus.
//     Econ. Stat. 13 (1995) 253-263), mean(d) / sqrt(S / N) with S the
//     Newey-West (Bartlett) long-run variance of d, whose bandwidth
//     follows Andrews' AR(1) plug-in rule (Econometrica 59 (1991)
//     817-858) after an AR(1) prewhitening (Andrews and Monahan,
//     Econometrica 60 (1992) 953-966); and the encompassing test of
//     Harvey, Leybourne and Newbold (J. Bus. Econ. Stat. 16 (1998)
//     254-259): in the regression e0 = beta (e0 - e1) + u (no intercept),
//     the t value of beta with the Newey-West variance of the score
//     u (e0 - e1). One-sided normal p-values.
//
//   whiteness_statistics: the Ljung-Box statistic Q = N (N + 2)
//     sum_(k=1..m) r_k^2 / (N - k) of the residual (chi^2(m) under
//     whiteness), and Haugh's independence statistic (J. Am. Stat. Assoc.
//     71 (1976) 378-385): e and each input prewhitened by AR models of
//     their own (orders <= 20 and <= 10 chosen by BIC, least squares), S =
//     N sum_k r_eu(k)^2 over k = -m..m (chi^2(nu (2m + 1)) under
//     independence whatever the colour of e). The chi^2 tail
//     probabilities are left to the caller.
//
//   ar_whitener: the AR model of a series by least squares, its order
//     chosen by BIC (the prewhitening above, and the noise model of
//     residtrace's coloured-noise candidate).
//
// Non-finite data propagate as in the formulas; clamps and maxima ignore
// a NaN operand (as Octave's min and max do).
#pragma once

#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <string>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid::residtrace {

namespace detail {

// max(a, b) and min(a, b) ignoring a NaN operand.
template <typename S>
S nan_max(S a, S b) {
  if (std::isnan(a)) return b;
  if (std::isnan(b)) return a;
  return a < b ? b : a;
}
template <typename S>
S nan_min(S a, S b) {
  if (std::isnan(a)) return b;
  if (std::isnan(b)) return a;
  return b < a ? b : a;
}
template <typename S>
S clamp97(S r) {
  return nan_min(nan_max(r, S(-0.97)), S(0.97));
}
// sum_k x(k + lag) y(k) over the overlap.
template <typename S>
S lagged_sum(const Vector<S>& x, const Vector<S>& y, Eigen::Index lag) {
  S s = 0;
  for (Eigen::Index k = 0; k + lag < x.size() && k < y.size(); ++k) {
    s += x(k + lag) * y(k);
  }
  return s;
}
template <typename S>
S mean(const Vector<S>& x) {
  S s = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k) s += x(k);
  return s / static_cast<S>(x.size());
}
template <typename S>
S sum_squares(const Vector<S>& x) {
  S s = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k) s += x(k) * x(k);
  return s;
}

}  // namespace detail

template <typename S>
struct LongRunVariance {
  S variance = 0;              // S of the test statistics
  Eigen::Index bandwidth = 0;  // Bartlett window length L
};

// The long-run variance of g: AR(1) prewhitening (rho clamped to
// +-0.97), the Bartlett window with Andrews' bandwidth L = min(floor(
// 1.1447 (a1 n)^(1/3)), floor(n / 4)), a1 = 4 r1^2 / ((1 - r1)^2 (1 +
// r1)^2) from the lag-one correlation r1 of the prewhitened series,
// recoloured by 1 / (1 - rho)^2; never below var(g) / N.
template <typename S>
LongRunVariance<S> newey_west(const Vector<S>& g) {
  LongRunVariance<S> out;
  const Eigen::Index N = g.size();
  const Vector<S> gc = g.array() - detail::mean(g);
  const S g0 = detail::sum_squares(gc) / static_cast<S>(N);
  out.variance = g0;
  if (!(g0 > 0) || !std::isfinite(g0)) return out;
  const S rho = detail::clamp97(detail::lagged_sum(gc, gc, 1) /
                                detail::sum_squares<S>(gc.head(N - 1)));
  const Vector<S> w = gc.tail(N - 1) - rho * gc.head(N - 1);
  const Eigen::Index n = w.size();
  const S w0 = detail::sum_squares(w) / static_cast<S>(n);
  const S r1 =
      detail::clamp97(detail::lagged_sum(w, w, 1) / detail::sum_squares(w));
  const S a1 = 4 * r1 * r1 / ((1 - r1) * (1 - r1) * (1 + r1) * (1 + r1));
  const S rule =
      std::floor(S(1.1447) * std::pow(a1 * static_cast<S>(n), S(1) / 3));
  const Eigen::Index L = static_cast<Eigen::Index>(
      detail::nan_min(rule, std::floor(static_cast<S>(n) / 4)));
  S Sw = w0;
  for (Eigen::Index l = 1; l <= L; ++l) {
    Sw += 2 * (1 - static_cast<S>(l) / static_cast<S>(L + 1)) *
          detail::lagged_sum(w, w, l) / static_cast<S>(n);
  }
  out.variance =
      detail::nan_max(Sw / ((1 - rho) * (1 - rho)), g0 / static_cast<S>(N));
  out.bandwidth = L;
  return out;
}

template <typename S>
struct DmTest {
  S score = 0;  // 1 - mean(e1^2) / mean(e0^2)
  S stat = 0;   // Diebold-Mariano statistic, its p-value, bandwidth
  S p = 1;
  Eigen::Index bandwidth = 0;
  S z = 0;  // encompassing t value and its p-value
  S p_corr = 0.5;
};

template <typename S>
Status dm_test(const Vector<S>& e0, const Vector<S>& e1, DmTest<S>* t) {
  if (e0.size() != e1.size()) {
    return dimension_mismatch("the two errors must have the same length");
  }
  if (e0.size() < 1) return bad_input("the errors must not be empty");
  const Eigen::Index N = e0.size();
  const Vector<S> d = e0.array().square() - e1.array().square();
  const Vector<S> sq1 = e1.array().square();
  const Vector<S> sq0 = e0.array().square();
  t->score = 1 - detail::mean(sq1) / detail::mean(sq0);
  const Vector<S> dc = e0 - e1;
  const S sdd = detail::sum_squares(dc);
  t->z = 0;
  if (sdd > 0) {
    const S beta = detail::lagged_sum(e0, dc, 0) / sdd;
    const Vector<S> g = (e0 - beta * dc).cwiseProduct(dc);
    const S v = newey_west(g).variance;
    if (v > 0) t->z = beta * sdd / std::sqrt(v * static_cast<S>(N));
  }
  t->p_corr = S(0.5) * std::erfc(t->z / std::sqrt(S(2)));
  const LongRunVariance<S> nw = newey_west(d);
  const S md = detail::mean(d);
  if (!(nw.variance > 0) || !std::isfinite(nw.variance)) {
    t->stat = 0;
    t->p = 1;
    t->bandwidth = 0;
    if (md > 0 && std::isfinite(md)) {
      t->stat = std::numeric_limits<S>::infinity();
      t->p = 0;
    }
    return Status::Ok();
  }
  t->stat = md / std::sqrt(nw.variance / static_cast<S>(N));
  t->p = S(0.5) * std::erfc(t->stat / std::sqrt(S(2)));
  t->bandwidth = nw.bandwidth;
  return Status::Ok();
}

// A(q) = [1 -c1 .. -cp] of an AR model of x, the order p <= pmax with the
// smallest BIC N log s2 + p log N (least squares on the samples p+1..N).
template <typename S>
Vector<S> ar_whitener(const Vector<S>& x, int pmax) {
  const Eigen::Index N = x.size();
  S best = std::numeric_limits<S>::infinity();
  Vector<S> a = Vector<S>::Ones(1);
  for (int p = 0; p <= pmax && p < N; ++p) {
    S s2 = 0;
    Vector<S> ap = Vector<S>::Ones(p + 1);
    if (p == 0) {
      s2 = detail::sum_squares(x) / static_cast<S>(N);
    } else {
      Matrix<S> X(N - p, p);
      for (int i = 1; i <= p; ++i) X.col(i - 1) = x.segment(p - i, N - p);
      const Vector<S> target = x.tail(N - p);
      const Vector<S> c =
          X.bdcSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(target);
      s2 = detail::sum_squares<S>(target - X * c) / static_cast<S>(N - p);
      ap.tail(p) = -c;
    }
    const S bic = static_cast<S>(N) * std::log(detail::nan_max(
                                          s2, std::numeric_limits<S>::min())) +
                  static_cast<S>(p) * std::log(static_cast<S>(N));
    if (bic < best) {
      best = bic;
      a = ap;
    }
  }
  return a;
}

// y = A(q) x, the FIR filter at rest before the first sample.
template <typename S>
Vector<S> fir(const Vector<S>& a, const Vector<S>& x) {
  Vector<S> y = Vector<S>::Zero(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    for (Eigen::Index i = 0; i < a.size() && i <= k; ++i) {
      y(k) += a(i) * x(k - i);
    }
  }
  return y;
}

template <typename S>
struct WhitenessStatistics {
  bool testable = true;
  std::string reason;  // why not, when not testable
  Vector<S> autocorr;  // r_k, k = 0..m
  S Q = 0;             // Ljung-Box, m degrees of freedom
  Matrix<S> xcorr;     // r_eu(k), k = -m..m, one column per input
  S S_indep = 0;       // Haugh, nu (2m + 1) degrees of freedom
};

// e: the residual; u: N-by-nu inputs; m: the largest lag; yscale: the
// output's RMS (a residual below 1e-10 yscale is zero to rounding, and
// not tested).
template <typename S>
Status whiteness_statistics(const Vector<S>& e,
                            const Eigen::Ref<const Matrix<S>>& u, int m,
                            S yscale, WhitenessStatistics<S>* w) {
  const Eigen::Index N = e.size();
  if (N < 1) return bad_input("the residual must not be empty");
  if (u.rows() != N) {
    return dimension_mismatch("the inputs need one row per residual sample");
  }
  if (m < 0) return bad_input("the largest lag must be >= 0");
  *w = WhitenessStatistics<S>();
  if (!e.allFinite()) {
    w->testable = false;
    w->reason = "the residual is not finite (the model output diverges)";
    return Status::Ok();
  }
  const Vector<S> ec = e.array() - detail::mean(e);
  if (std::sqrt(detail::sum_squares(e) / static_cast<S>(N)) <=
      S(1e-10) * yscale) {
    w->testable = false;
    w->reason = "the residual is zero to rounding: nothing left to test";
    return Status::Ok();
  }
  if ((ec.array() == 0).all()) {
    w->testable = false;
    w->reason = "the residual is constant: nothing left to test";
    return Status::Ok();
  }
  const S s0 = detail::sum_squares(ec);
  w->autocorr.resize(m + 1);
  for (int k = 0; k <= m; ++k)
    w->autocorr(k) = detail::lagged_sum(ec, ec, k) / s0;
  S q = 0;
  for (int k = 1; k <= m; ++k) {
    q += w->autocorr(k) * w->autocorr(k) / static_cast<S>(N - k);
  }
  w->Q = static_cast<S>(N) * static_cast<S>(N + 2) * q;
  const Eigen::Index nu = u.cols();
  w->xcorr = Matrix<S>::Zero(2 * m + 1, nu);
  const int cap = static_cast<int>(N / 20);
  const Vector<S> ew = fir(ar_whitener(ec, std::min(20, cap)), ec);
  const S see = detail::sum_squares(ew);
  for (Eigen::Index j = 0; j < nu; ++j) {
    const Vector<S> uj = u.col(j);
    const Vector<S> uc = uj.array() - detail::mean(uj);
    if ((uc.array() == 0).all()) continue;
    const Vector<S> uw = fir(ar_whitener(uc, std::min(10, cap)), uc);
    const S scale = std::sqrt(detail::sum_squares(uw) * see);
    S sq = 0;
    for (int i = 0; i <= 2 * m; ++i) {
      const int k = i - m;  // e(t) against u(t - k)
      const S c = k >= 0 ? detail::lagged_sum(ew, uw, k)
                         : detail::lagged_sum(uw, ew, -k);
      w->xcorr(i, j) = c / scale;
      sq += w->xcorr(i, j) * w->xcorr(i, j);
    }
    w->S_indep += static_cast<S>(N) * sq;
  }
  return Status::Ok();
}

}  // namespace ctid::residtrace
