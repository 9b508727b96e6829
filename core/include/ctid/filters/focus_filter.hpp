// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The Focus prefilter of the transfer-function estimators on time-domain
// data: a Butterworth band [w1, w2] (rad/s) of a given order, a low-pass of
// cut-off w2 times, for w1 > 0, a high-pass of cut-off w1 (no low-pass when
// w2 is at or above the Nyquist frequency pi/Ts), each discretised by the
// Tustin map with prewarping at its cut-off:
//
//   analog poles p_k = w exp(i pi (2k + n - 1) / (2n)), k = 1 .. n,
//   w = 2/Ts tan(wc Ts / 2),  z_k = (1 + p_k Ts/2) / (1 - p_k Ts/2),
//
// zeros at z = -1 (low-pass) or z = 1 (high-pass), unit gain at z = 1
// (low-pass) or z = -1 (high-pass). Fitting L y by G L u weights the output
// error by |L|^2, the band's weighting of the System Identification
// Toolbox's Focus option.
#pragma once

#include <cmath>
#include <complex>

#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/discrete_filter.hpp"

namespace ctid {

// The Butterworth low-pass (high = false) or high-pass of order n and
// cut-off wc (rad/s), prewarped Tustin, as C(q^-1) = num / den.
template <typename S>
DiscreteTransferFunction<S> butterworth_tustin(int n, S wc, S ts, bool high) {
  using Complex = std::complex<S>;
  const S pi = S(3.14159265358979323846264338327950288L);
  const S w = 2 / ts * std::tan(wc * ts / 2);
  Eigen::Matrix<Complex, Eigen::Dynamic, 1> poles(n), zeros(n);
  for (int k = 1; k <= n; ++k) {
    const Complex p =
        w * std::exp(Complex(0, pi * S(2 * k + n - 1) / S(2 * n)));
    poles(k - 1) = (S(1) + p * (ts / 2)) / (S(1) - p * (ts / 2));
    zeros(k - 1) = high ? S(1) : S(-1);
  }
  DiscreteTransferFunction<S> f;
  f.denominator = monic_from_roots<S>(poles).real();
  f.numerator = monic_from_roots<S>(zeros).real();
  const S at = high ? S(-1) : S(1);
  // (descending powers of z: reversed, ascending for Horner)
  const S gain = std::abs(polynomial_value<S>(f.denominator.reverse(), at) /
                          polynomial_value<S>(f.numerator.reverse(), at));
  f.numerator *= gain;
  return f;
}

// The Focus band [w1, w2] (0 <= w1 < w2, rad/s) of order n at sampling
// interval ts; w2 at or above pi/ts: no low-pass, w1 = 0: no high-pass.
template <typename S>
Status focus_band_filter(int n, S w1, S w2, S ts,
                         DiscreteTransferFunction<S>& filter) {
  if (n < 1) return bad_input("the Focus filter order must be >= 1");
  if (!(ts > 0) || !std::isfinite(ts)) {
    return bad_input("the sampling interval must be finite and > 0");
  }
  if (!(w1 >= 0) || !(w2 > w1) || !std::isfinite(w1) || std::isnan(w2)) {
    return bad_input("the Focus band must be [w1 w2] with 0 <= w1 < w2");
  }
  const S pi = S(3.14159265358979323846264338327950288L);
  filter.numerator = Vector<S>::Ones(1);
  filter.denominator = Vector<S>::Ones(1);
  if (w2 < pi / ts) filter = butterworth_tustin<S>(n, w2, ts, false);
  if (w1 > 0) {
    const DiscreteTransferFunction<S> high =
        butterworth_tustin<S>(n, w1, ts, true);
    filter.numerator = convolve<S>(filter.numerator, high.numerator);
    filter.denominator = convolve<S>(filter.denominator, high.denominator);
  }
  return Status::Ok();
}

// Filters each column of x (N-by-m) in place by the filter, at rest before
// the first sample.
template <typename S>
void apply_filter(const DiscreteTransferFunction<S>& filter, Matrix<S>& x) {
  DiscreteFilter<S> f;
  f.configure(filter);
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    f.reset();
    for (Eigen::Index k = 0; k < x.rows(); ++k) x(k, j) = f.step(x(k, j));
  }
}

}  // namespace ctid
