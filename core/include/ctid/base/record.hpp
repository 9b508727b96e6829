// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// A sampled input-output record as the batch functions read it, without
// copying: y (N samples), u (N-by-nu, column-major) and either a constant
// sampling interval or the N sampling instants (irregular sampling).
#pragma once

#include <cmath>
#include <string>

#include "ctid/base/model.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

// t_k - t_(k-1) of a record with N samples, a constant interval ts when
// `instants` is null; for k = 0 the first interval of the record.
template <typename S>
S sampling_interval(const S* instants, S ts, Eigen::Index num_samples,
                    Eigen::Index k) {
  if (instants == nullptr) return ts;
  if (num_samples < 2) return S(1);
  if (k == 0) return instants[1] - instants[0];
  return instants[k] - instants[k - 1];
}

template <typename S>
struct RecordView {
  const S* y = nullptr;
  const S* u = nullptr;  // column-major N-by-num_inputs
  Eigen::Index num_samples = 0;
  Eigen::Index num_inputs = 0;
  S ts = 0;                     // sampling interval when `instants` is null
  const S* instants = nullptr;  // N strictly increasing instants, or null

  S u_at(Eigen::Index k, Eigen::Index j) const {
    return u[j * num_samples + k];
  }
  // t_k - t_(k-1); for k = 0 the first interval of the record.
  S interval(Eigen::Index k) const {
    return sampling_interval(instants, ts, num_samples, k);
  }
};

template <typename S>
Status validate_record(const RecordView<S>& record, const ModelOrders& orders) {
  if (record.num_inputs != orders.num_inputs()) {
    return dimension_mismatch(
        "the data have " + std::to_string(record.num_inputs) +
        " input(s) but nb and nk give " + std::to_string(orders.num_inputs()));
  }
  if (record.num_samples < orders.num_parameters()) {
    return bad_input("the data have " + std::to_string(record.num_samples) +
                     " samples, fewer than the " +
                     std::to_string(orders.num_parameters()) +
                     " parameters to estimate");
  }
  for (Eigen::Index k = 0; k < record.num_samples; ++k) {
    if (!std::isfinite(record.y[k])) {
      return bad_input("y must be finite (sample " + std::to_string(k + 1) +
                       " is not)");
    }
  }
  for (Eigen::Index i = 0; i < record.num_samples * record.num_inputs; ++i) {
    if (!std::isfinite(record.u[i])) {
      return bad_input("u must be finite (sample " +
                       std::to_string(i % record.num_samples + 1) + " is not)");
    }
  }
  if (record.instants == nullptr) {
    if (!(record.ts > 0) || !std::isfinite(record.ts)) {
      return bad_input("the sampling interval Ts must be finite and > 0");
    }
    return Status::Ok();
  }
  for (Eigen::Index k = 0; k < record.num_samples; ++k) {
    if (!std::isfinite(record.instants[k])) {
      return bad_input("the sampling instants must be finite");
    }
    if (k > 0 && !(record.instants[k] > record.instants[k - 1])) {
      return bad_input(
          "the sampling instants must be strictly increasing "
          "(sample " +
          std::to_string(k + 1) + " is not)");
    }
  }
  if (orders.max_delay() > 0) {
    return bad_input("nk must be 0 for irregularly sampled data");
  }
  return Status::Ok();
}

}  // namespace ctid
