// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Inverse of a static polynomial without constant term, sample by sample:
// x_k solves
//
//   g(x) = beta_1 x + beta_2 x^2 + .. + beta_L x^L = v_k,
//
// the output nonlinearity of a Wiener block (Hammerstein-Wiener refined IV,
// Ni, Garnier & Gilson, IET CTA 2013; CONTSID's NL_W).
//
// When g is strictly monotonic (g' has no real root where it changes sign)
// the solution is unique: Newton steps kept inside a bracket that starts
// at Fujiwara's bound of the roots of g(x) - v (a bisection step whenever
// Newton leaves it), to a few eps. Otherwise x_k is the real root of
// g(x) - v_k nearest to x_(k-1) (x_0: the root nearest to v_0), from the
// eigenvalues of the companion matrix and polished by Newton; a sample
// with no real root is a numerical failure.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

namespace detail {

// Is the polynomial c (ascending powers, degree >= 2) strictly monotonic on
// the real line: does its derivative change sign at none of its real roots?
template <typename S>
bool strictly_monotonic(const Vector<S>& c) {
  const Vector<S> dc = polynomial_derivative(c);
  if (dc.size() < 2) return true;  // g' constant
  const auto r = polynomial_roots(dc);
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const S re = r(i).real();
    if (std::abs(r(i).imag()) > S(1e-9) * (1 + std::abs(r(i)))) continue;
    const S h = S(1e-6) * (1 + std::abs(re));
    if (polynomial_value(dc, re - h) * polynomial_value(dc, re + h) < 0) {
      return false;
    }
  }
  return true;
}

// The unique root of g(x) = v for a strictly monotonic g (c: coefficients
// of g, ascending, c_0 = 0), bracketed Newton.
template <typename S>
S monotonic_inverse(const Vector<S>& c, const Vector<S>& dc, S v) {
  const Eigen::Index n = c.size() - 1;
  const S lead = c(n);
  // Fujiwara's bound on the roots of g(x) - v:
  // 2 max(|c_(n-k) / c_n|^(1/k), |v / (2 c_n)|^(1/n)), k = 1 .. n-1.
  S bound = 0;
  for (Eigen::Index k = 1; k < n; ++k) {
    bound = std::max(bound, std::pow(std::abs(c(n - k) / lead), S(1) / S(k)));
  }
  bound = 2 * std::max(bound, std::pow(std::abs(v / (2 * lead)), S(1) / S(n)));
  S lo = -bound;
  S hi = bound;
  const bool rising = lead > 0;  // a monotonic g has odd degree
  S x = v / c(1);                // the linear guess
  if (!std::isfinite(x) || x <= lo || x >= hi) x = 0;
  for (int it = 0; it < 200; ++it) {
    const S f = polynomial_value(c, x) - v;
    if ((f > 0) == rising) {
      hi = x;  // x above the root
    } else {
      lo = x;
    }
    S next = x - f / polynomial_value(dc, x);
    if (!(next >= lo && next <= hi) || !std::isfinite(next)) {
      next = (lo + hi) / 2;
    }
    const bool done =
        std::abs(next - x) <=
        4 * std::numeric_limits<S>::epsilon() * std::max(S(1), std::abs(next));
    x = next;
    if (done) break;
  }
  return x;
}

}  // namespace detail

// x[k] for v[k], k = 0 .. n-1 (x may alias v). beta: beta_1 .. beta_L.
template <typename S>
Status invert_polynomial(const Vector<S>& beta, const S* v, Eigen::Index n,
                         S* x) {
  Eigen::Index degree = beta.size();
  while (degree > 0 && beta(degree - 1) == S(0)) --degree;
  if (degree == 0) return bad_input("the polynomial is identically zero");
  if (!beta.head(degree).allFinite()) {
    return bad_input("the polynomial coefficients must be finite");
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(v[k])) return bad_input("the values must be finite");
  }
  if (degree == 1) {
    for (Eigen::Index k = 0; k < n; ++k) x[k] = v[k] / beta(0);
    return Status::Ok();
  }
  Vector<S> c = Vector<S>::Zero(degree + 1);  // g(x), ascending, c_0 = 0
  c.tail(degree) = beta.head(degree);
  const Vector<S> dc = polynomial_derivative(c);
  if (detail::strictly_monotonic(c)) {
    for (Eigen::Index k = 0; k < n; ++k) {
      x[k] = detail::monotonic_inverse(c, dc, v[k]);
    }
    return Status::Ok();
  }
  S previous = n > 0 ? v[0] : S(0);
  for (Eigen::Index k = 0; k < n; ++k) {
    const S target = v[k];
    c(0) = -target;
    const auto r = polynomial_roots(c);
    c(0) = 0;
    S best = 0;
    S gap = std::numeric_limits<S>::infinity();
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      if (std::abs(r(i).imag()) > S(1e-8) * (1 + std::abs(r(i)))) continue;
      const S distance = std::abs(r(i).real() - previous);
      if (distance < gap) {
        gap = distance;
        best = r(i).real();
      }
    }
    if (!std::isfinite(gap)) {
      return numerical_failure("the polynomial takes no value " +
                               std::to_string(static_cast<double>(target)) +
                               " (sample " + std::to_string(k + 1) + ")");
    }
    // Newton polish, each step kept only when it lowers the residual.
    S residual = std::abs(polynomial_value(c, best) - target);
    for (int it = 0; it < 3; ++it) {
      const S slope = polynomial_value(dc, best);
      if (!(std::abs(slope) > 0)) break;
      const S next = best - (polynomial_value(c, best) - target) / slope;
      const S r_next = std::abs(polynomial_value(c, next) - target);
      if (!(r_next < residual)) break;
      best = next;
      residual = r_next;
    }
    x[k] = best;
    previous = best;
  }
  return Status::Ok();
}

}  // namespace ctid
