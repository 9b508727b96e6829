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
//
// F = p^n + f1 p^(n-1) + .. + fn is given by f = [f1 .. fn].
#pragma once

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

}  // namespace ctid::residtrace
