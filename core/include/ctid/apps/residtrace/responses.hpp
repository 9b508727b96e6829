// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The filtered signals of residtrace on a regular grid, from the core's
// batch filters (filters/batch_filters.hpp):
//
//   filtered_derivatives: p^i x / F(p), i = 0..n, the filter at rest at
//     the first sample, x held by the exact ZOH or FOH between samples
//     (the SVF/prefilter outputs of the SRIVC regression, thesis eqs.
//     2.8-2.13);
//   free_responses: the responses of F(p) h = 0 from the n unit initial
//     conditions h^(l)(t_1) = delta_il, a basis of the model's free
//     responses (the initial-condition terms residtrace fits by least
//     squares). For an unstable F they grow without bound: from the first
//     sample with a non-finite entry on, the rows are 0 (for an F with a
//     non-finite coefficient, from the second sample on).
//   zero_lag_velocity: the velocity of a measured output for the sign of
//     the velocity (structure_fit.hpp, eq. 4.17) without phase lag.
//
// F = p^n + f1 p^(n-1) + .. + fn is given by f = [f1 .. fn].
#pragma once

#include <cmath>
#include <string>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/batch_filters.hpp"

namespace ctid::residtrace {

template <typename S>
Status validate_responses(const Vector<S>& f, S ts) {
  if (!(ts > 0) || !std::isfinite(ts)) {
    return bad_input("the sampling interval must be finite and > 0");
  }
  if (!f.allFinite()) return bad_input("F must have finite coefficients");
  return Status::Ok();
}

template <typename S>
Status filtered_derivatives(const Vector<S>& f, S ts, InterSample rule,
                            const S* x, Eigen::Index N, Matrix<S>& out) {
  Status status = validate_responses(f, ts);
  if (!status.ok()) return status;
  if (f.size() < 1) return bad_input("F must have order >= 1");
  if (rule == InterSample::kTrapezoid) {
    return bad_input("the signal must be held by ZOH or FOH");
  }
  batch::Clock<S> clock;
  clock.ts = ts;
  clock.n = N;
  batch::filter_derivatives<S>(f, S(1), rule, clock, x, out);
  return Status::Ok();
}

template <typename S>
Status free_responses(const Vector<S>& f, S ts, Eigen::Index N,
                      Matrix<S>& out) {
  if (!(ts > 0) || !std::isfinite(ts)) {
    return bad_input("the sampling interval must be finite and > 0");
  }
  if (N < 0) return bad_input("the number of samples must be >= 0");
  if (f.size() == 0 || N == 0 || !f.allFinite()) {
    out = Matrix<S>::Zero(N, f.size());
    if (f.size() > 0 && N > 0) out(0, 0) = 1;
    return Status::Ok();
  }
  batch::Clock<S> clock;
  clock.ts = ts;
  clock.n = N;
  batch::free_responses<S>(f, clock, out);
  for (Eigen::Index k = 0; k < N; ++k) {
    if (!out.row(k).allFinite()) {
      out.bottomRows(N - k).setZero();
      break;
    }
  }
  return Status::Ok();
}

// The velocity of the measured output y (N samples, held by FOH) for the
// sign-of-velocity channel: the SVF derivative p lambda/(p + lambda) y run
// forward, then lambda/(p + lambda) run backward, so that the result is
// p lambda^2/(lambda^2 + w^2) y without phase lag (the zero crossings that
// sign(v) depends on are not delayed). With output_itself (a first-order
// model, whose output is read as a velocity) y itself, smoothed the same
// way without the derivative.
template <typename S>
Status zero_lag_velocity(const S* y, Eigen::Index N, S ts, S lambda,
                         bool output_itself, Vector<S>* v) {
  if (!(lambda > 0) || !std::isfinite(lambda)) {
    return bad_input("the velocity filter's bandwidth must be finite and > 0");
  }
  const Vector<S> f = Vector<S>::Constant(1, lambda);
  Matrix<S> D;
  Status status = filtered_derivatives<S>(f, ts, InterSample::kFoh, y, N, D);
  if (!status.ok()) return status;
  // forward, then the time-reversed signal through lambda/(p + lambda)
  Vector<S> back = lambda * D.col(output_itself ? 0 : 1).reverse();
  status = filtered_derivatives<S>(f, ts, InterSample::kFoh, back.data(), N, D);
  if (!status.ok()) return status;
  *v = (lambda * D.col(0)).reverse();
  return Status::Ok();
}

}  // namespace ctid::residtrace
