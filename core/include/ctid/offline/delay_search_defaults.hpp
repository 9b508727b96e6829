// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The data-dependent defaults of a delay search (delay_search.hpp; the
// toolbox's tfsrivc, tfsrivc_init, tfrivc, procsrivc and tfcoe's starts),
// computed once here for every host:
//
// - TdMax, as CONTSID documents it: "calculated by maximizing the cross
//   correlation function of the input-output data". The lag of the largest
//   |r_yu(k)| = |sum_t y~(t + k) u~(t)| (y~, u~ without their means) over
//   0 <= k <= half the record, plus 10 sampling intervals (the input's own
//   correlation, e.g. a PRBS clock period, can move the peak a few samples
//   before the impulse response's), at least the smaller of a tenth of the
//   record and 50 sampling intervals, at most half the record. Irregular
//   instants: the signals are first put on a regular grid of their median
//   interval (u held, y linear), unless that grid would have more than 10
//   times their number of samples (then the lower bound alone). The range
//   then holds twice the start delay and twice TdMin, at most half the
//   record, and the grid is extended up to half the record while its
//   minimum lies at its upper end.
// - StepMax: one grid spacing (TdMax - TdMin) / (NumTd - 1), at least one
//   sampling interval (a Gauss-Newton step on the delay never jumps over the
//   grid's minimum).
//
//   DelayRangeRequest<double> given;   // td_max, step_max NaN: defaults
//   given.td_min = 0.1;
//   DelayRange<double> range;
//   Status s = delay_search_range(record, given, &range);
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ctid/base/record.hpp"
#include "ctid/base/status.hpp"

namespace ctid {

// The median of the record's sampling intervals (its ts when regular).
template <typename S>
S median_sampling_interval(const RecordView<S>& r) {
  if (r.instants == nullptr) return r.ts;
  std::vector<S> dt;
  for (Eigen::Index k = 1; k < r.num_samples; ++k)
    dt.push_back(r.instants[k] - r.instants[k - 1]);
  if (dt.empty()) return 0;
  std::sort(dt.begin(), dt.end());
  const std::size_t m = dt.size();
  return m % 2 ? dt[m / 2] : (dt[m / 2 - 1] + dt[m / 2]) / 2;
}

// The span t_N - t_1 of the record.
template <typename S>
S record_span(const RecordView<S>& r) {
  if (r.num_samples < 1) return 0;
  if (r.instants == nullptr) return r.ts * static_cast<S>(r.num_samples - 1);
  return r.instants[r.num_samples - 1] - r.instants[0];
}

// The cross-correlation TdMax of the header comment, from y and the first
// input column of the record.
template <typename S>
S default_td_max(const RecordView<S>& r) {
  const Eigen::Index n = r.num_samples;
  const S span = record_span(r);
  const S h = median_sampling_interval(r);
  const S lower = std::min(span / 10, 50 * h);
  if (n < 4 || !(h > 0)) return lower;
  std::vector<S> y(r.y, r.y + n), u(r.u, r.u + n);
  if (r.instants != nullptr) {
    const S* t = r.instants;
    S spread = 0;
    for (Eigen::Index k = 1; k < n; ++k)
      spread = std::max(spread, std::abs(t[k] - t[k - 1] - h));
    if (spread > S(1e-9) * h) {
      if (span / h > 10 * static_cast<S>(n)) return lower;  // too sparse
      const Eigen::Index m =
          static_cast<Eigen::Index>(std::floor(span / h + S(1e-10))) + 1;
      y.assign(m, 0);
      u.assign(m, 0);
      Eigen::Index i = 0;  // t[i] <= tg < t[i + 1]
      for (Eigen::Index k = 0; k < m; ++k) {
        const S tg = t[0] + static_cast<S>(k) * h;
        // (an instant within 1e-9 h of the grid point is on it: the grid's
        // roundoff does not move u to the sample before)
        while (i + 1 < n && t[i + 1] <= tg + S(1e-9) * h) ++i;
        u[k] = r.u[i];
        if (i + 1 < n) {
          const S a = std::max(S(0), (tg - t[i]) / (t[i + 1] - t[i]));
          y[k] = (1 - a) * r.y[i] + a * r.y[i + 1];
        } else {
          y[k] = r.y[n - 1];
        }
      }
    }
  }
  const Eigen::Index m = static_cast<Eigen::Index>(y.size());
  S ym = 0, um = 0;
  for (Eigen::Index k = 0; k < m; ++k) {
    ym += y[k];
    um += u[k];
  }
  ym /= static_cast<S>(m);
  um /= static_cast<S>(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    y[k] -= ym;
    u[k] -= um;
  }
  const Eigen::Index lags = (m - 1) / 2;
  Eigen::Index best = 0;
  S peak = -1;
  for (Eigen::Index lag = 0; lag <= lags; ++lag) {
    S c = 0;
    for (Eigen::Index k = 0; k + lag < m; ++k) c += y[k + lag] * u[k];
    if (std::abs(c) > peak) {
      peak = std::abs(c);
      best = lag;
    }
  }
  return std::max(lower, std::min((static_cast<S>(best) + 10) * h, span / 2));
}

// What a user gave: NaN for td_max, step_max and td_start is "not given".
template <typename S>
struct DelayRangeRequest {
  S td_min = 0;
  S td_max = std::numeric_limits<S>::quiet_NaN();
  int num_td = 50;
  S step_max = std::numeric_limits<S>::quiet_NaN();
  S td_start = std::numeric_limits<S>::quiet_NaN();  // the start delay
};

template <typename S>
struct DelayRange {
  S td_max = 0;
  S step_max = 0;
  // Half the record when td_max is the default (the grid is extended up to
  // it while its minimum lies at its upper end), else 0.
  S extend_limit = 0;
  bool td_max_from_data = false;
};

// The range of a delay search with the defaults of the header comment for
// what the request leaves out.
template <typename S>
Status delay_search_range(const RecordView<S>& record,
                          const DelayRangeRequest<S>& given,
                          DelayRange<S>* range) {
  if (range == nullptr) return bad_input("the result must not be null");
  if (record.num_samples < 2 || record.y == nullptr || record.u == nullptr) {
    return bad_input("the record needs two samples and an input");
  }
  if (!(given.td_min >= 0) || !std::isfinite(given.td_min)) {
    return Status(ErrorCode::kBadOption, "TdMin must be a finite scalar >= 0");
  }
  if (given.num_td < 1) {
    return Status(ErrorCode::kBadOption, "NumTd must be an integer >= 1");
  }
  const S half = record_span(record) / 2;
  DelayRange<S> out;
  out.td_max_from_data = std::isnan(given.td_max);
  if (out.td_max_from_data) {
    S td_max = std::max(default_td_max(record), 2 * given.td_min);
    if (!std::isnan(given.td_start))
      td_max = std::max(td_max, 2 * given.td_start);
    out.td_max = std::min(td_max, half);
    out.extend_limit = half;
  } else {
    out.td_max = given.td_max;
  }
  out.step_max = given.step_max;
  if (std::isnan(given.step_max)) {
    out.step_max = std::max((out.td_max - given.td_min) /
                                static_cast<S>(std::max(given.num_td - 1, 1)),
                            median_sampling_interval(record));
  }
  *range = out;
  return Status::Ok();
}

}  // namespace ctid
