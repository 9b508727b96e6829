// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Whether the data determine the real poles of a converged refined-IV fit.
//
// A converged fit may still hold a real pole the samples cannot see:
// first-order data fitted with a second-order structure converge with the
// extra pole at |p| Ts up to 5e6, or with a pole whose standard error
// exceeds its magnitude. Both make the structure over-parameterised in
// the sense of the fit's status (RivResult::determined), whatever the
// engine's stopping rule said:
//
// - |p| h > 1000: the mode dies out within a thousandth of a sampling
//   interval; in the band up to the Nyquist frequency it changes the
//   response by at most pi / 1000 (residtrace removes such poles from its
//   candidates' fits by the same bound);
// - with one denominator, sd(p) > |p|: the time constant is not
//   distinguished from 0. The standard error is the first-order one of
//   the root of F(p) = p^n + f_1 p^(n-1) + .. + f_n as a function of f:
//   dp/df_k = -p^(n-k) / F'(p), sd(p)^2 = J P_f J^T, P_f the covariance of
//   f (thesis eq. 2.13, the SRIVC covariance).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/refined_iv_problem.hpp"

namespace ctid {

namespace riv_detail {

inline std::string format_number(const char* format, double x) {
  char text[64];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

}  // namespace riv_detail

// The sampling interval the bound |p| h > 1000 uses: Ts, or the median
// interval of an irregular record.
template <typename S>
S typical_interval(const RivData<S>& data) {
  if (data.instants == nullptr || data.num_samples < 2) return data.ts;
  std::vector<S> steps(static_cast<std::size_t>(data.num_samples - 1));
  for (Eigen::Index i = 1; i < data.num_samples; ++i) {
    steps[static_cast<std::size_t>(i - 1)] =
        data.instants[i] - data.instants[i - 1];
  }
  const std::size_t n = steps.size();
  std::nth_element(steps.begin(), steps.begin() + n / 2, steps.end());
  const S upper = steps[n / 2];
  if (n % 2 == 1) return upper;
  const S lower = *std::max_element(steps.begin(), steps.begin() + n / 2);
  return (lower + upper) / 2;
}

// The first real pole of the denominators of theta (layout of
// refined_iv_problem.hpp: f of each group first) that the data do not
// determine, in words; "" when every real pole is determined. covariance
// is theta's (original time); h the sampling interval.
template <typename S>
std::string undetermined_pole(const RivProblem<S>& problem,
                              const Vector<S>& theta,
                              const Matrix<S>& covariance, S h) {
  const int groups = problem.num_groups();
  Eigen::Index at = 0;
  for (int g = 0; g < groups; ++g) {
    const int n = problem.nf[static_cast<std::size_t>(g)];
    if (n < 1 || at + n > theta.size()) return "";
    // F_g in ascending powers: f_n, .., f_1, 1
    Vector<S> ascending(n + 1);
    ascending(n) = 1;
    for (int k = 1; k <= n; ++k) ascending(n - k) = theta(at + k - 1);
    if (!ascending.allFinite()) return "";
    // poles at p = 0 (trailing zero coefficients, declared integrators)
    // are exact: the roots of F without them are judged
    int zeros = 0;
    while (zeros < n && ascending(zeros) == 0) ++zeros;
    const auto p = n - zeros >= 1
                       ? polynomial_roots<S>(ascending.tail(n + 1 - zeros))
                       : Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>();
    const Vector<S> dF = polynomial_derivative<S>(ascending);
    const bool with_sd = groups == 1 && covariance.rows() >= n &&
                         covariance.cols() >= n &&
                         covariance.topLeftCorner(n, n).allFinite();
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      const S root = p(i).real();
      if (p(i).imag() != 0 || root == 0) continue;
      if (std::abs(root) * h > S(1000)) {
        return "a pole at p = " +
               riv_detail::format_number("%.4g", double(root)) +
               " has |p| Ts = " +
               riv_detail::format_number("%.3g", double(std::abs(root) * h)) +
               " > 1000";
      }
      if (!with_sd) continue;
      const S slope = polynomial_value<S>(dF, root);
      Vector<S> J(n);
      for (int k = 1; k <= n; ++k) J(k - 1) = -std::pow(root, n - k) / slope;
      if (!J.allFinite()) continue;  // a repeated pole: no first-order sd
      const S variance =
          (J.transpose() * covariance.topLeftCorner(n, n) * J)(0, 0);
      const S sd = std::sqrt(std::max(variance, S(0)));
      if (sd > std::abs(root)) {
        return "the pole at p = " +
               riv_detail::format_number("%.4g", double(root)) +
               " has a standard error of " +
               riv_detail::format_number("%.3g", double(sd)) +
               ": its time constant is not distinguished from 0";
      }
    }
    at += n;
  }
  return "";
}

}  // namespace ctid
